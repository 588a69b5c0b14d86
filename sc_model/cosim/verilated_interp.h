// The verilated RTL (rtl/interp_top.sv) behind the golden model's interface: reset(),
// tick(inputs), outputs(). Model is one of rtl_models.h (an arch, fast or with VCD tracing)
// or a sweep or soak variant's Vinterp_top.
// Idea: one clock = set the inputs, evaluate with clk low, then with clk high (the rising
// edge); every output is a register, so after the second eval the ports hold the outputs
// of that edge, which is what GoldenInterp::outputs() holds after tick().
// The RTL's assertions (verilated with --assert) print their message when one fails; the
// harness then throws std::runtime_error from that clock instead of letting Verilator
// abort the process, so a command reports the failure and exits like on any other error.
#pragma once
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "interp_ports.h"
#include "verilated.h"

namespace ncinterp {

template <class Model>
class VerilatedInterp {
 public:
  // Instance name: VCD scopes are SystemC.interp.interp_top.<...>, as in the system
  // model's VCDs (docs/waves.md), so one GTKWave save file opens both.
  static constexpr const char* kScope = "SystemC.interp";

  // PortPosition::from_rtl sign-extends from the port's C type (IData).
  static_assert(InterpConfig{}.pos_width == 32, "PosWidth must match the verilated C type");

  // `built`: the parameters the model was verilated with (rtl_built_config(arch) for the
  // models of this build, rtl_models.h; a sweep or soak variant's own, rtl_variant/). cfg
  // must have them: only feed_modulus, an input port, is free.
  VerilatedInterp(const InterpConfig& cfg, const InterpConfig& built)
      : context_(std::make_unique<VerilatedContext>()),
        model_(std::make_unique<Model>(context_.get(), kScope)),
        modulus_(cfg.feed_modulus),
        rapid_step_(cfg.rapid_step),
        accel_step_(cfg.accel_step) {
    if (!cfg.same_parameters(built))
      throw std::invalid_argument(
          std::string("the verilated RTL (") + arch_name(built.arch) + ", W " +
          std::to_string(built.inc_width) + ") is built with other parameters than the configuration's");
    // A failed assertion stops the model ($stop) on the thread's context: this one.
    context_->fatalOnError(false);
    Verilated::threadContextp(context_.get());
    reset();
  }
  ~VerilatedInterp() {
    if (Verilated::threadContextp() == context_.get())
      Verilated::threadContextp(Verilated::defaultContextp());
  }
  VerilatedInterp(const VerilatedInterp&) = delete;
  VerilatedInterp& operator=(const VerilatedInterp&) = delete;

  // One edge with rst_ni low (synchronous reset); dump as for tick().
  template <class Dump>
  void reset(Dump&& dump) {
    Model& m = *model_;
    m.rst_ni = 0;
    m.feed_modulus_i = modulus_;
    m.rapid_step_i = rapid_step_;
    m.accel_step_i = accel_step_;
    m.frame_i = 0;
    m.frame_valid_i = 0;
    m.tape_end_i = 0;
    m.feed_override_i = m.rapid_override_i = kOverrideOne;
    clock(dump);
    m.rst_ni = 1;
  }
  void reset() { reset([](int) {}); }

  // One rising edge with these inputs. dump(phase) runs after each eval (0: clk low,
  // 1: after the edge), e.g. to write a VCD sample.
  template <class Dump>
  void tick(const InterpInputs& in, Dump&& dump) {
    Model& m = *model_;
    m.frame_i = in.frame;
    m.frame_valid_i = in.frame_valid;
    m.tape_end_i = in.tape_end;
    m.hold_i = in.hold;
    m.start_i = in.start;
    m.feed_override_i = in.feed_override;
    m.rapid_override_i = in.rapid_override;
    m.estop_i = in.estop;
    m.limit_x_i = in.limit_x;
    m.limit_y_i = in.limit_y;
    m.optional_stop_i = in.optional_stop;
    clock(dump);
  }
  void tick(const InterpInputs& in) { tick(in, [](int) {}); }

  bool frame_ready() const { return model_->frame_ready_o; }

  // The outputs (interp_outputs.def), port by port, written into o field by field. A
  // caller that keeps its outputs (the system model's engine, every clock) passes its own
  // struct: building a temporary and copying it costs more than the model's evaluation
  // of an idle clock (the copy's wide loads stall on the byte-wide stores just made).
  void read_outputs(InterpOutputs& o) const {
    const Model& m = *model_;
#define INTERP_OUTPUT(name, kind, width) o.name = Port##kind::from_rtl(m.name##_o);
#include "interp_outputs.def"
#undef INTERP_OUTPUT
  }
  InterpOutputs outputs() const {
    InterpOutputs o;
    read_outputs(o);
    return o;
  }

  // Field-by-field equality with a golden output struct, without building one.
  bool same_as(const InterpOutputs& g) const {
    const Model& m = *model_;
    return true
#define INTERP_OUTPUT(name, kind, width) &&g.name == Port##kind::from_rtl(m.name##_o)
#include "interp_outputs.def"
#undef INTERP_OUTPUT
        ;
  }

  Model& model() { return *model_; }
  VerilatedContext& context() { return *context_; }

 private:
  template <class Dump>
  void clock(Dump&& dump) {
    Model& m = *model_;
    m.clk_i = 0;
    m.eval();
    dump(0);
    m.clk_i = 1;
    m.eval();
    dump(1);
    if (context_->gotError())
      throw std::runtime_error("the RTL stopped on a failed assertion (its message is above)");
  }

  std::unique_ptr<VerilatedContext> context_;
  std::unique_ptr<Model> model_;
  uint64_t modulus_, rapid_step_, accel_step_;
};

}  // namespace ncinterp
