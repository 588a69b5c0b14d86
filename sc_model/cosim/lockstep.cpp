// Lock-step cosimulation on this build's verilated model of the configured arch (see
// lockstep.h; the loop is lockstep_loop.h).
#include "lockstep.h"

#include "lockstep_loop.h"
#include "rtl_models.h"
#include "verilated_interp.h"

namespace ncinterp::cosim {

Result run_lockstep(const std::vector<uint8_t>& frames, const Options& options,
                    const Observer& observer) {
  const Arch arch = options.config.arch;
  return with_rtl_model(arch, [&](auto model) {
    VerilatedInterp<typename decltype(model)::type> rtl(options.config, rtl_built_config(arch));
    return run_lockstep_on(rtl, frames, options, observer);
  });
}

}  // namespace ncinterp::cosim
