// The SystemC system (see system_top.h).
#include "system_top.h"

namespace ncinterp::system {

namespace {

sc_core::sc_time period_of(double clock_hz) { return sc_core::sc_time(1.0 / clock_hz, sc_core::SC_SEC); }

}  // namespace

SystemTop::SystemTop(sc_core::sc_module_name name, const SystemSetup& setup, FrameSource source,
                     const tape::Program& program)
    : sc_core::sc_module(name),
      setup_(setup),
      clk_("clk", period_of(setup.clock_hz), 0.5, period_of(setup.clock_hz), true),
      reader_("reader", std::move(source)),
      monitor_(program, setup.config.feed_modulus) {
  reader_.clk_i(clk_);
  reader_.rst_ni(signals_.rst_ni);
  reader_.frame_ready_i(signals_.frame_ready_o);
  reader_.frame_o(signals_.frame_i);
  reader_.frame_valid_o(signals_.frame_valid_i);
  reader_.tape_end_o(signals_.tape_end_i);
  engine_ = setup.engine == EngineKind::kGolden
                ? make_golden_engine(setup.config, clk_, signals_)
                : make_rtl_engine(setup.config, clk_, signals_, !setup.vcd_path.empty());
  signals_.feed_modulus_i.write(setup.config.feed_modulus);
  signals_.rst_ni.write(false);
  SC_HAS_PROCESS(SystemTop);
  SC_METHOD(falling_edge);
  sensitive << clk_.negedge_event();
  dont_initialize();
}

SystemTop::~SystemTop() = default;

void SystemTop::start() {
  if (!setup_.vcd_path.empty() && setup_.vcd_window.from == 0) {
    engine_->open_vcd(setup_.vcd_path);
    vcd_open_ = true;
  }
}

void SystemTop::finish() {
  if (!vcd_open_) return;
  engine_->close_vcd();
  vcd_open_ = false;
  vcd_closed_ = true;
}

InterpOutputs SystemTop::sample() const {
  const InterpConfig& cfg = setup_.config;
  InterpOutputs o;
#define INTERP_OUTPUT(name, kind, width) \
  o.name = Port##kind::from_signal(signals_.name##_o.read(), width);
#include "interp_outputs.def"
#undef INTERP_OUTPUT
  return o;
}

void SystemTop::falling_edge() {
  const bool in_reset = !signals_.rst_ni.read();
  if (!in_reset) ++cycle_;  // the first falling edge follows the reset edge: cycle 0
  monitor_.observe(cycle_, sample());
  if (in_reset) signals_.rst_ni.write(true);

  // VCD window: open half a clock before edge `from`, close half a clock after edge `to`.
  if (!setup_.vcd_path.empty()) {
    if (!vcd_open_ && !vcd_closed_ && cycle_ + 1 >= setup_.vcd_window.from) {
      engine_->open_vcd(setup_.vcd_path);
      vcd_open_ = true;
    } else if (vcd_open_ && cycle_ >= setup_.vcd_window.to) {
      engine_->close_vcd();
      vcd_open_ = false;
      vcd_closed_ = true;
    }
  }
  if (setup_.progress && cycle_ % setup_.progress_every == 0)
    setup_.progress(cycle_, monitor_.pulse_block());
  if (monitor_.finished()) {
    sc_core::sc_stop();
  } else if (cycle_ >= setup_.max_cycles) {
    limit_reached_ = true;
    sc_core::sc_stop();
  }
}

}  // namespace ncinterp::system
