// The verilated interpolators of this build: interp_top in each microarchitecture (Arch),
// without and with tracing, and the one place that maps an Arch to its model class.
// Idea: both RTL forms are verilated into every binary (rtl/CMakeLists.txt), so a command
// plays, co-verifies or checks whichever arch it is asked for; code that runs a verilated
// model is a template over the model class and is instantiated here for each of them.
// with_rtl_model(arch, f) calls f(RtlModelTag<Model>{}) with the model of that arch.
#pragma once
#include "Vinterp_parallel.h"
#include "Vinterp_parallel_trace.h"
#include "Vinterp_serial.h"
#include "Vinterp_serial_trace.h"
#include "interp_ports.h"

namespace ncinterp {

template <class Model>
struct RtlModelTag {
  using type = Model;
};

// The parameters a verilated model is built with: the defaults, in its arch.
inline InterpConfig rtl_built_config(Arch arch) {
  InterpConfig c;
  c.arch = arch;
  return c;
}

// f(RtlModelTag<Model>{}) with the fast (untraced) model of `arch`.
template <class F>
decltype(auto) with_rtl_model(Arch arch, F&& f) {
  if (arch == Arch::kSerial) return f(RtlModelTag<Vinterp_serial>{});
  return f(RtlModelTag<Vinterp_parallel>{});
}

// f(RtlModelTag<Model>{}) with the trace-enabled model of `arch` (VCD).
template <class F>
decltype(auto) with_rtl_trace_model(Arch arch, F&& f) {
  if (arch == Arch::kSerial) return f(RtlModelTag<Vinterp_serial_trace>{});
  return f(RtlModelTag<Vinterp_parallel_trace>{});
}

}  // namespace ncinterp
