// Differential tape fuzzer: any byte stream is a tape of frames (bit 7 = parity). The
// verilated RTL and the golden model play it in lock step; every output is compared after
// every clock (sc_model/cosim). Then the software tape reader (sw/host/tape) must agree with
// the interpolator on the outcome: a program both accept (same motion blocks, same end
// position), or the same error code, block N and frame offset.
// Idea: the two engines and the reader are three implementations of one contract (docs/
// tape-format.md, docs/interpolator.md); random tapes reach corners no hand-written test
// names. The work per input is bounded: a fast reader (one clock per frame), a small feed
// modulus (a block takes at most 2 10^4 clocks, a saturated one 2^k for 2^k iterations),
// at most kMaxCycles clocks; a run cut there is still compared clock by clock, only the
// outcome is not. NCINTERP_FUZZ_STATS=1 prints how many inputs ended how (at exit);
// NCINTERP_FUZZ_INJECT=wrong_direction plants a fault in the golden model.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fuzz_check.h"
#include "lockstep.h"
#include "tape/tape.h"

namespace {

using ncinterp::cosim::Result;

constexpr size_t kMaxFrames = 4096;
constexpr uint64_t kMaxCycles = 100'000;
// 60 f_clk 10^3 for f_clk = 1/3 Hz: F = 1 (0.001/min) gives the longest non-saturated block,
// ceil(M / F) = 2 10^4 clocks; any F >= M / 2^k saturates (2^k clocks).
constexpr uint64_t kFeedModulus = 20'000;

// Inputs per way a run ended (done, tape error, cycle limit), printed at exit on request.
struct EndCounts {
  uint64_t n[3] = {0, 0, 0};
  ~EndCounts() {
    if (std::getenv("NCINTERP_FUZZ_STATS"))
      std::fprintf(stderr, "tape_lockstep: %llu done, %llu tape error, %llu cycle limit\n",
                   static_cast<unsigned long long>(n[0]), static_cast<unsigned long long>(n[1]),
                   static_cast<unsigned long long>(n[2]));
  }
} end_counts;

std::string outcome_of(const Result& r) {
  if (r.end == Result::End::kDone) return "done";
  return "error code " + std::to_string(r.last.error_code) + ", block N" +
         std::to_string(r.last.error_block) + ", offset " + std::to_string(r.last.error_offset);
}

// The software reader's outcome against the interpolator's (run to done or a tape error).
void compare_with_reader(const std::vector<uint8_t>& frames, const Result& r) {
  const ncinterp::tape::Format format;  // the interpolator's default widths
  const ncinterp::tape::ParseResult p = ncinterp::tape::parse_frames_partial(frames, format);
  const std::string interp = outcome_of(r);
  if (r.end == Result::End::kDone) {
    if (p.error)
      ncinterp::fuzz::fail("interpolator: done, tape reader: " + ncinterp::tape::describe(*p.error) +
                           " (code " + std::to_string(p.error->code) + ")");
  } else {
    if (!p.error) ncinterp::fuzz::fail("interpolator: " + interp + ", tape reader: accepted");
    if (p.error->code != r.last.error_code || p.error->block != r.last.error_block ||
        p.error->offset != r.last.error_offset)
      ncinterp::fuzz::fail("interpolator: " + interp + ", tape reader: code " +
                           std::to_string(p.error->code) + ", " + ncinterp::tape::describe(*p.error));
  }
  // Every block before the end or the error played, and nothing else.
  if (r.stats.blocks != p.program.blocks.size())
    ncinterp::fuzz::fail("interpolator (" + interp + ") loaded " + std::to_string(r.stats.blocks) +
                         " motion blocks, the tape reader read " +
                         std::to_string(p.program.blocks.size()));
  int64_t x = 0, y = 0;
  for (const ncinterp::tape::Block& b : p.program.blocks) x += b.dx, y += b.dy;
  // Position counters are PosWidth = 32 bits wide and wrap.
  if (r.last.pos_x != static_cast<int32_t>(x) || r.last.pos_y != static_cast<int32_t>(y))
    ncinterp::fuzz::fail("interpolator (" + interp + ") ends at (" + std::to_string(r.last.pos_x) +
                         ", " + std::to_string(r.last.pos_y) + "), the tape reader's blocks sum to (" +
                         std::to_string(x) + ", " + std::to_string(y) + ")");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > kMaxFrames) return -1;  // not added to the corpus
  const std::vector<uint8_t> frames(data, data + size);
  ncinterp::cosim::Options options;
  options.config.feed_modulus = kFeedModulus;
  options.cycles_per_frame = 1;
  options.max_cycles = kMaxCycles;
  // Planted bug: the golden model's X dir inverted while a block plays (must be found).
  if (ncinterp::fuzz::injected("wrong_direction"))
    options.fault = {ncinterp::GoldenInterp::Fault::kWrongDirection, 0, 0};
  const Result r = ncinterp::cosim::run_lockstep(frames, options);
  if (r.end == Result::End::kMismatch)
    ncinterp::fuzz::fail("RTL and golden model differ: " + ncinterp::cosim::describe(*r.mismatch));
  ++end_counts.n[r.end == Result::End::kDone ? 0 : r.end == Result::End::kTapeError ? 1 : 2];
  if (r.end != Result::End::kCycleLimit) compare_with_reader(frames, r);
  return 0;
}
