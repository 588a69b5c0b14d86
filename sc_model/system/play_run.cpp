// One `play` run (see play_run.h): configuration, cycle limit, VCD window and file, the
// SystemC simulation, and the monitors' summary.
#include "play_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "arc_prepare.h"
#include "atomic_file.h"
#include "frame_source.h"
#include "system_top.h"

namespace ncinterp::system {

namespace {
// Bytes per clock of a VCD, from the measurements of docs/waves.md section 2 (gear.nc):
// golden 45 bytes per busy cycle; RTL 205 per busy cycle, 128 over the tape lead-in, about
// 190 over a whole part (0.7 GB for 3.78 M cycles). Rough on purpose: it is for a warning.
constexpr double kGoldenVcdBytesPerCycle = 45.0;
constexpr double kRtlVcdBytesPerCycle = 190.0;
}  // namespace

uint64_t cycle_limit_for(const tape::Program& program, size_t frames, uint64_t cycles_per_frame,
                         const InterpConfig& cfg) {
  uint64_t total = static_cast<uint64_t>(frames) * cycles_per_frame;
  for (const tape::Block& b : program.blocks) {
    // Iterations: 2^k for a line; fewer than 2^(k+1) for an arc, whose k is that of its
    // largest coordinate about the centre (<= |I| + |X|, |J| + |Y|), and whose preparation
    // in the decoder takes ArcPrepare::clocks (docs/interpolator.md 3.5).
    const bool arc = tape::is_arc(b.motion);
    const uint64_t m = static_cast<uint64_t>(
        arc ? std::max(std::llabs(b.i) + std::llabs(b.dx), std::llabs(b.j) + std::llabs(b.dy))
            : std::max(std::llabs(b.dx), std::llabs(b.dy)));
    const unsigned k = bit_length(m);
    const uint64_t iterations = arc ? 2ull << k : 1ull << k;
    const uint64_t prepare = arc ? ArcPrepare::clocks(cfg.inc_width, cfg.serial(), iterations) : 0;
    // M 2^k / S: ceil(M / F) for G01, the rapid step's rate for G00.
    const unsigned __int128 step = line_step(b, cfg);
    const uint64_t programmed =
        step ? static_cast<uint64_t>(((static_cast<unsigned __int128>(cfg.feed_modulus) << k) + step - 1) / step) : 0;
    // Saturated, one iteration per clock (per 2P clocks with BitSerial: SerialDda).
    const uint64_t iteration = cfg.serial() ? SerialDda::iteration_clocks(cfg.inc_width) : 1;
    total += std::max(iterations * iteration + 1, programmed) + prepare + 3;
    total += cfg.ramp_clocks(iterations);
  }
  return 2 * total + 100000;
}

uint64_t vcd_size_estimate(EngineKind engine, uint64_t cycles) {
  // Bytes per clock of whole-part VCDs (examples/gear.nc, docs/waves.md "VCD size"): the
  // RTL engine's VCD also holds the decoder and DDA internals.
  const double per_cycle = engine == EngineKind::kRtl ? kRtlVcdBytesPerCycle : kGoldenVcdBytesPerCycle;
  return static_cast<uint64_t>(per_cycle * static_cast<double>(cycles));
}

PlayResult run_play(const std::vector<uint8_t>& frames, const tape::Program& program,
                    const PlayOptions& opt) {
  static bool used = false;
  if (used) throw std::logic_error("run_play: SystemC cannot be restarted in one process");
  used = true;
  if (!(opt.clock_hz >= 1.0 && opt.clock_hz <= 1e11))
    throw std::runtime_error("--clock-hz must be between 1 and 1e11");
  if (!(opt.reader_cps > 0.0)) throw std::runtime_error("--reader-cps must be positive");

  // No SystemC banner or info messages on stdout: the CLI's output is its own.
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);

  PlayResult r;
  r.config = interp_config(opt.clock_hz, {}, opt.rapid_mm_min, opt.accel_mm_s2);  // the default widths, in the chosen arch
  r.config.arch = opt.arch;
  r.clock_hz = opt.clock_hz;
  r.accel_mm_s2 = opt.accel_mm_s2;
  r.reader_cps = opt.reader_cps;
  r.cycles_per_frame = FrameSource::cycles_per_frame_for(opt.clock_hz, opt.reader_cps);
  r.frames = frames.size();
  r.blocks_on_tape = program.blocks.size();
  r.max_cycles = opt.max_cycles ? opt.max_cycles
                                : cycle_limit_for(program, frames.size(), r.cycles_per_frame, r.config) +
                                      last_event_cycle(opt.events);

  std::unique_ptr<AtomicOutputFile> vcd;
  SystemSetup setup;
  setup.config = r.config;
  setup.engine = opt.engine;
  setup.clock_hz = opt.clock_hz;
  setup.max_cycles = r.max_cycles;
  setup.every_clock = opt.every_clock;
  r.vcd_path = opt.vcd_path;
  if (!opt.vcd_path.empty()) {
    r.vcd_window = resolve_vcd_window(opt.vcd_from, opt.vcd_to, frames, r.config,
                                      r.cycles_per_frame, r.max_cycles);
    if (!opt.vcd_file) vcd = std::make_unique<AtomicOutputFile>(opt.vcd_path);
    setup.vcd_path = opt.vcd_file ? opt.vcd_file->temp_path() : vcd->temp_path();
    setup.vcd_window = r.vcd_window;
    if (opt.vcd_estimate) {
      // The limit is twice the expected run (cycle_limit_for); the window cuts it further.
      const uint64_t expected_end = std::min(r.vcd_window.to, r.max_cycles / 2);
      const uint64_t cycles = expected_end > r.vcd_window.from ? expected_end - r.vcd_window.from : 0;
      opt.vcd_estimate(vcd_size_estimate(opt.engine, cycles), cycles);
    }
  }
  if (opt.progress) {
    const size_t blocks = program.blocks.size();
    setup.progress = [&opt, blocks](uint64_t cycle, size_t done) { opt.progress(cycle, done, blocks); };
  }

  const auto t0 = std::chrono::steady_clock::now();
  auto top = std::make_unique<SystemTop>("SystemC", setup, FrameSource(frames, r.cycles_per_frame, opt.events),
                                         program);
  sc_core::sc_start();
  top->finish();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.summary = top->monitor().finish(top->outputs());
  r.limit_reached = top->limit_reached();
  r.frames_taken = top->source().frames_taken();

  if (!opt.vcd_path.empty()) {
    if (!top->vcd_started())
      throw std::runtime_error(opt.vcd_path + ": the VCD window starts at cycle " +
                               std::to_string(r.vcd_window.from) + ", after the run ended at cycle " +
                               std::to_string(r.summary.cycles));
    if (r.ok() || r.stopped()) {  // a run that fails on its tape writes none
      if (vcd) vcd->commit();
      r.vcd_written = true;
    }
  }
  return r;
}

}  // namespace ncinterp::system
