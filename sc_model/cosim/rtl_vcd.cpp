// VCD window of the RTL (see rtl_vcd.h).
#include "rtl_vcd.h"

#include <stdexcept>

#include "atomic_file.h"

#include "frame_source.h"
#include "rtl_models.h"
#include "vcd_time_base.h"
#include "verilated_interp.h"
#include "verilated_vcd_c.h"

namespace ncinterp::cosim {

void write_rtl_vcd(const std::vector<uint8_t>& frames, const Options& options, double clock_hz,
                   uint64_t first_cycle, uint64_t last_cycle, const std::string& path) {
  AtomicOutputFile out(path);  // removed again unless committed
  write_rtl_vcd(frames, options, clock_hz, first_cycle, last_cycle, out);
  out.commit();
}

void write_rtl_vcd(const std::vector<uint8_t>& frames, const Options& options, double clock_hz,
                   uint64_t first_cycle, uint64_t last_cycle, AtomicOutputFile& out) {
  with_rtl_trace_model(options.config.arch, [&](auto model) {
    VerilatedInterp<typename decltype(model)::type> rtl(options.config,
                                                        rtl_built_config(options.config.arch));
    rtl.context().traceEverOn(true);
    VerilatedVcdC vcd;
    rtl.model().trace(&vcd, 99);
    vcd.open(out.temp_path().c_str());
    if (!vcd.isOpen()) throw std::runtime_error(out.path() + ": cannot open for writing");
    const uint64_t period = vcd_period_ps(clock_hz);
    FrameSource source(frames, options.cycles_per_frame, options.events);
    for (uint64_t cycle = 1; cycle <= last_cycle; ++cycle) {
      const bool ready = rtl.frame_ready();
      const bool dumping = cycle >= first_cycle;
      rtl.tick(source.inputs(), [&](int phase) {
        if (dumping) vcd.dump(vcd_edge_ps(cycle, phase, period));
      });
      source.clock(ready);
    }
    vcd.close();
  });
}

}  // namespace ncinterp::cosim
