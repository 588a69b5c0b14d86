// The golden engine: GoldenInterp stepped directly, and SystemC's own VCD tracer over the
// system's wave signals, named and sized like the RTL's ports in Verilator's VCD (engine.h).
#include <systemc>

#include "engine.h"
#include "interp_signals.h"
#include "interp_top.h"

namespace ncinterp::system {

namespace {

class GoldenEngine : public Engine {
 public:
  GoldenEngine(const InterpConfig& cfg, const WaveSignals& waves) : model_(cfg), waves_(waves) {}
  ~GoldenEngine() override { close_vcd(); }

  void reset() override { model_.reset(); }
  void tick(const InterpInputs& in) override { model_.tick(in); }
  const InterpOutputs& outputs() const override { return model_.outputs(); }
  uint64_t quiet_ticks(const InterpInputs& in) const override { return model_.quiet_ticks(in); }
  void skip(uint64_t n) override { model_.skip(n); }

  void open_vcd(const std::string& path) override {
    close_vcd();
    // sc_create_vcd_trace_file appends ".vcd" itself.
    const std::string base =
        path.size() > 4 && path.compare(path.size() - 4, 4, ".vcd") == 0 ? path.substr(0, path.size() - 4)
                                                                          : path;
    file_ = sc_core::sc_create_vcd_trace_file(base.c_str());
    file_->set_time_unit(1, sc_core::SC_PS);  // Verilator's VCD is in ps as well
    const std::string p = "interp.interp_top.";
    const WaveSignals& s = waves_;
    sc_core::sc_trace(file_, s.clk_i, p + "clk_i");
    sc_core::sc_trace(file_, s.rst_ni, p + "rst_ni");
    trace(s.feed_modulus_i, p + "feed_modulus_i", model_.config().modulus_width);
    trace(s.frame_i, p + "frame_i", 8);
    sc_core::sc_trace(file_, s.frame_valid_i, p + "frame_valid_i");
    sc_core::sc_trace(file_, s.tape_end_i, p + "tape_end_i");
    const InterpConfig& cfg = model_.config();
#define INTERP_OUTPUT(name, kind, width) trace_output<Port##kind>(s.name##_o, p + #name "_o", width);
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

  GoldenInterp model_;
  const WaveSignals& waves_;
  sc_core::sc_trace_file* file_ = nullptr;
};

}  // namespace

std::unique_ptr<Engine> make_golden_engine(const InterpConfig& cfg, const WaveSignals& waves) {
  return std::make_unique<GoldenEngine>(cfg, waves);
}

}  // namespace ncinterp::system
