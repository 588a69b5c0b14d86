// The RTL engine: rtl/interp_top.sv of the configured arch verilated as plain C++
// (VerilatedInterp, the cosim's wrapper), stepped directly, and Verilator's own VCD tracer
// (VerilatedVcdC), opened on demand. Without a VCD the model is the one built without
// tracing, which is faster; with one it is the trace-enabled one (rtl_models.h).
#include <stdexcept>

#include "engine.h"
#include "rtl_models.h"
#include "verilated_interp.h"
#include "vcd_time_base.h"
#include "verilated_vcd_c.h"

namespace ncinterp::system {

namespace {

template <class Model, bool kTraced>
class RtlEngine : public Engine {
 public:
  RtlEngine(const InterpConfig& cfg, double clock_hz)
      : rtl_(cfg, rtl_built_config(cfg.arch)),
        period_ps_(vcd_period_ps(clock_hz)) {}
  ~RtlEngine() override { close_vcd(); }

  void reset() override {
    cycle_ = 0;
    rtl_.reset([this](int phase) { dump(phase); });
    rtl_.read_outputs(out_);
  }
  void tick(const InterpInputs& in) override {
    ++cycle_;
    if (vcd_)
      rtl_.tick(in, [this](int phase) { dump(phase); });
    else
      rtl_.tick(in);
    rtl_.read_outputs(out_);
  }
  const InterpOutputs& outputs() const override { return out_; }

  void open_vcd(const std::string& path) override {
    if constexpr (!kTraced) {
      throw std::logic_error("RTL engine built without tracing");
    } else {
      close_vcd();
      rtl_.context().traceEverOn(true);
      // trace() registers the model with a fresh tracer; it must precede open().
      vcd_ = std::make_unique<VerilatedVcdC>();
      rtl_.model().trace(vcd_.get(), 99);
      vcd_->open(path.c_str());
      if (!vcd_->isOpen()) throw std::runtime_error(path + ": cannot open for writing");
    }
  }

  void close_vcd() override {
    if (!vcd_) return;
    vcd_->close();
    vcd_.reset();
  }

 private:
  void dump(int phase) {
    if (vcd_) vcd_->dump(vcd_edge_ps(cycle_, phase, period_ps_));
  }

  VerilatedInterp<Model> rtl_;
  uint64_t period_ps_;
  uint64_t cycle_ = 0;
  InterpOutputs out_;
  std::unique_ptr<VerilatedVcdC> vcd_;
};

}  // namespace

std::unique_ptr<Engine> make_rtl_engine(const InterpConfig& cfg, double clock_hz, bool with_trace) {
  // The verilated models have the RTL's default widths: the configuration must match.
  if (!cfg.same_parameters(rtl_built_config(cfg.arch)))
    throw std::runtime_error("the verilated RTL has the default widths only");
  if (with_trace)
    return with_rtl_trace_model(cfg.arch, [&](auto model) -> std::unique_ptr<Engine> {
      return std::make_unique<RtlEngine<typename decltype(model)::type, true>>(cfg, clock_hz);
    });
  return with_rtl_model(cfg.arch, [&](auto model) -> std::unique_ptr<Engine> {
    return std::make_unique<RtlEngine<typename decltype(model)::type, false>>(cfg, clock_hz);
  });
}

}  // namespace ncinterp::system
