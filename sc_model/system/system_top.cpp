// The SystemC system (see system_top.h).
#include "system_top.h"

#include <algorithm>

#include "vcd_time_base.h"

namespace ncinterp::system {

SystemTop::SystemTop(sc_core::sc_module_name name, const SystemSetup& setup, FrameSource source,
                     const tape::Program& program)
    : sc_core::sc_module(name),
      setup_(setup),
      // In ps, SystemC's default time resolution and the VCDs' time unit.
      period_ps_(vcd_period_ps(setup.clock_hz)),
      source_(std::move(source)),
      engine_(setup.engine == EngineKind::kGolden
                  ? make_golden_engine(setup.config, waves_)
                  : make_rtl_engine(setup.config, setup.clock_hz, !setup.vcd_path.empty())),
      monitor_(program, setup.config) {
  waves_.feed_modulus_i.write(setup.config.feed_modulus);
  SC_HAS_PROCESS(SystemTop);
  SC_THREAD(run);
}

SystemTop::~SystemTop() = default;

void SystemTop::finish() {
  if (!vcd_open_) return;
  engine_->close_vcd();
  vcd_open_ = false;
  vcd_closed_ = true;
}

void SystemTop::catch_up() {
  // The fall after edge cycle_ is the clock-low half before edge cycle_ + 1.
  const sc_core::sc_time fall = sc_core::sc_time::from_value(vcd_edge_ps(cycle_ + 1, 0, period_ps_));
  if (fall > sc_core::sc_time_stamp()) wait(fall - sc_core::sc_time_stamp());
}

void SystemTop::drive_waves(bool clk) {
  waves_.clk_i.write(clk);
  waves_.rst_ni.write(!in_reset_);
  waves_.write_inputs(source_.inputs());
  // Before the reset edge the outputs keep the signals' initial 0 (the RTL's are unknown).
  if (reset_taken_) waves_.write_outputs(engine_->outputs(), setup_.config);
}

void SystemTop::open_vcd() {
  drive_waves(false);
  engine_->open_vcd(setup_.vcd_path);
  vcd_open_ = true;
}

void SystemTop::run() {
  const sc_core::sc_time half = sc_core::sc_time::from_value(period_ps_ / 2);
  // t = 0, clock low before the reset edge: a window from cycle 0 opens here.
  if (!setup_.vcd_path.empty() && setup_.vcd_window.from == 0) open_vcd();
  wait(sc_core::sc_time::from_value(period_ps_));
  engine_->reset();
  reset_taken_ = true;
  for (;;) {
    // Edge cycle_ has been taken. In a window: its half clock high, then the fall.
    if (vcd_open_) {
      drive_waves(true);
      wait(half);
    }
    const bool more = falling_edge();  // may open or close the window at this fall
    if (vcd_open_) drive_waves(false);
    if (!more) break;
    if (const uint64_t n = quiet_clocks()) {
      engine_->skip(n);
      source_.skip(n);
      cycle_ += n;
      monitor_.observe_quiet(cycle_, engine_->outputs());
      if (setup_.progress && cycle_ / setup_.progress_every != (cycle_ - n) / setup_.progress_every)
        setup_.progress(cycle_, monitor_.pulse_block());
    }
    // The next rising edge: the engine sees the reader's inputs from before it, the reader
    // the engine's frame_ready from before it.
    const bool ready = engine_->outputs().frame_ready;
    engine_->tick(source_.inputs());
    source_.clock(ready);
    ++cycle_;
    if (vcd_open_) wait(half);
  }
  catch_up();
  sc_core::sc_stop();
}

uint64_t SystemTop::quiet_clocks() const {
  if (setup_.every_clock || vcd_open_) return 0;
  uint64_t n = engine_->quiet_ticks(source_.inputs());
  if (n == 0) return 0;
  n = std::min(n, source_.steady_clocks());
  // Leave the last clock before the limit, and the fall before a VCD window opens, to
  // falling_edge().
  n = std::min(n, setup_.max_cycles > cycle_ + 1 ? setup_.max_cycles - cycle_ - 1 : 0);
  if (!setup_.vcd_path.empty() && !vcd_closed_)
    n = std::min(n, setup_.vcd_window.from > cycle_ + 2 ? setup_.vcd_window.from - cycle_ - 2 : 0);
  return n;
}

bool SystemTop::falling_edge() {
  monitor_.observe(cycle_, engine_->outputs());
  in_reset_ = false;

  // VCD window: open half a clock before edge `from`, close half a clock after edge `to`.
  if (!setup_.vcd_path.empty()) {
    if (!vcd_open_ && !vcd_closed_ && cycle_ + 1 >= setup_.vcd_window.from) {
      catch_up();
      open_vcd();
    } else if (vcd_open_ && cycle_ >= setup_.vcd_window.to) {
      engine_->close_vcd();
      vcd_open_ = false;
      vcd_closed_ = true;
    }
  }
  if (setup_.progress && cycle_ % setup_.progress_every == 0)
    setup_.progress(cycle_, monitor_.pulse_block());
  if (monitor_.finished() || source_.run_over(engine_->outputs())) return false;
  if (cycle_ >= setup_.max_cycles) {
    limit_reached_ = true;
    return false;
  }
  return true;
}

}  // namespace ncinterp::system
