// The RTL engine: rtl/interp_top.sv verilated for SystemC (target ncinterp_rtl_sc, class
// Vinterp_top_sc) and Verilator's own SystemC VCD tracer (VerilatedVcdSc), opened and
// closed on demand.
// Built only when the verilated model exists (NCINTERP_HAVE_RTL_SC); otherwise asking for
// it is a clear error.
#include <stdexcept>

#include "engine.h"

#ifdef NCINTERP_HAVE_RTL_SC
#include <verilated.h>
#include <verilated_vcd_sc.h>

#include "Vinterp_top_sc.h"
#endif

namespace ncinterp::system {

#ifdef NCINTERP_HAVE_RTL_SC

namespace {

class RtlEngine : public Engine {
 public:
  RtlEngine(sc_core::sc_signal_in_if<bool>& clk, InterpSignals& s, bool with_trace)
      : with_trace_((Verilated::traceEverOn(with_trace), with_trace)), model_("interp") {
    bind_engine(model_, clk, s);
  }
  ~RtlEngine() override { close_vcd(); }

  void open_vcd(const std::string& path) override {
    if (!with_trace_) throw std::logic_error("RTL engine built without tracing");
    close_vcd();
    // trace() registers the model with a fresh tracer; it must precede open().
    vcd_ = std::make_unique<VerilatedVcdSc>();
    model_.trace(vcd_.get(), 99);
    vcd_->open(path.c_str());
  }

  void close_vcd() override {
    if (!vcd_) return;
    vcd_->close();
    // The tracer registered itself with the kernel but does not unregister on destruction;
    // its sc_trace_file base is private, hence the C-style cast.
    sc_core::sc_get_curr_simcontext()->remove_trace_file((sc_core::sc_trace_file*)vcd_.get());
    vcd_.reset();
  }

 private:
  bool with_trace_;
  Vinterp_top_sc model_;
  std::unique_ptr<VerilatedVcdSc> vcd_;
};

}  // namespace

bool rtl_engine_available() { return true; }

std::unique_ptr<Engine> make_rtl_engine(const InterpConfig& cfg,
                                        sc_core::sc_signal_in_if<bool>& clk,
                                        InterpSignals& signals, bool with_trace) {
  // The verilated model has the RTL's default parameters: the configuration must match.
  if (!cfg.same_parameters(InterpConfig{}))
    throw std::runtime_error("the verilated RTL has the default widths only");
  return std::make_unique<RtlEngine>(clk, signals, with_trace);
}

#else

bool rtl_engine_available() { return false; }

std::unique_ptr<Engine> make_rtl_engine(const InterpConfig&, sc_core::sc_signal_in_if<bool>&,
                                        InterpSignals&, bool) {
  throw std::runtime_error(
      "this build has no verilated SystemC RTL (target ncinterp_rtl_sc); use --engine golden");
}

#endif

}  // namespace ncinterp::system
