// The golden engine: GoldenInterpModule plus SystemC's own VCD tracer over its ports,
// named and sized like the RTL's ports in Verilator's VCD (see engine.h).
#include <systemc>

#include "engine.h"
#include "golden_module.h"

namespace ncinterp::system {

namespace {

class GoldenEngine : public Engine {
 public:
  GoldenEngine(const InterpConfig& cfg, sc_core::sc_signal_in_if<bool>& clk, InterpSignals& s)
      : cfg_(cfg), clk_(clk), s_(s), module_("interp", cfg) {
    bind_engine(module_, clk, s);
  }
  ~GoldenEngine() override { close_vcd(); }

  void open_vcd(const std::string& path) override {
    close_vcd();
    // sc_create_vcd_trace_file appends ".vcd" itself.
    const std::string base =
        path.size() > 4 && path.compare(path.size() - 4, 4, ".vcd") == 0 ? path.substr(0, path.size() - 4)
                                                                          : path;
    file_ = sc_core::sc_create_vcd_trace_file(base.c_str());
    file_->set_time_unit(1, sc_core::SC_PS);  // Verilator's VCD is in ps as well
    const std::string p = "interp.interp_top.";
    sc_core::sc_trace(file_, clk_, p + "clk_i");
    sc_core::sc_trace(file_, s_.rst_ni, p + "rst_ni");
    trace(s_.feed_modulus_i, p + "feed_modulus_i", cfg_.modulus_width);
    trace(s_.frame_i, p + "frame_i", 8);
    sc_core::sc_trace(file_, s_.frame_valid_i, p + "frame_valid_i");
    sc_core::sc_trace(file_, s_.tape_end_i, p + "tape_end_i");
    const InterpConfig& cfg = cfg_;
#define INTERP_OUTPUT(name, kind, width) \
  trace_output<Port##kind>(s_.name##_o, p + #name "_o", width);
#include "interp_outputs.def"
#undef INTERP_OUTPUT
  }

  void close_vcd() override {
    if (!file_) return;
    sc_core::sc_close_vcd_trace_file(file_);
    file_ = nullptr;
  }

 private:
  // Multi-bit ports with the RTL's width (the signal's value is stable storage).
  template <class T>
  void trace(const sc_core::sc_signal<T>& sig, const std::string& name, unsigned width) {
    sc_core::sc_trace(file_, sig.read(), name, static_cast<int>(width));
  }

  // An output (interp_outputs.def): one bit as SystemC traces a bool, else with its width.
  template <class Kind, class T>
  void trace_output(const sc_core::sc_signal<T>& sig, const std::string& name, unsigned width) {
    if constexpr (Kind::kOneBit)
      sc_core::sc_trace(file_, sig, name);
    else
      trace(sig, name, width);
  }

  InterpConfig cfg_;
  sc_core::sc_signal_in_if<bool>& clk_;
  InterpSignals& s_;
  GoldenInterpModule module_;
  sc_core::sc_trace_file* file_ = nullptr;
};

}  // namespace

std::unique_ptr<Engine> make_golden_engine(const InterpConfig& cfg,
                                           sc_core::sc_signal_in_if<bool>& clk,
                                           InterpSignals& signals) {
  return std::make_unique<GoldenEngine>(cfg, clk, signals);
}

}  // namespace ncinterp::system
