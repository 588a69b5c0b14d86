// Test support for the checker tests (see checker_test_support.h).
#include "checker_test_support.h"

#include "engine_run.h"
#include "frame_source.h"

namespace ncinterp::checker::test {

std::vector<uint8_t> frames_of(const tape::Program& program, const tape::Format& format) {
  return tape::add_parity(tape::format_program(program, format));
}

tape::Program random_line_program(std::mt19937& rng, int blocks, unsigned max_bits,
                                  uint64_t modulus, uint64_t min_clocks, uint64_t max_clocks) {
  tape::Program p;
  std::uniform_int_distribution<unsigned> bits(0, max_bits);
  std::uniform_int_distribution<int> sign(0, 1);
  std::uniform_int_distribution<uint64_t> clocks(min_clocks, max_clocks);
  auto value = [&]() -> int64_t {
    const unsigned b = bits(rng);
    if (b == 0) return 0;
    const int64_t v = std::uniform_int_distribution<int64_t>(int64_t{1} << (b - 1), (int64_t{1} << b) - 1)(rng);
    return sign(rng) ? -v : v;
  };
  for (int k = 0; k < blocks; ++k) {
    tape::Block b;
    b.n = static_cast<uint32_t>(k + 1);
    b.dx = value();
    b.dy = value();
    b.feed = std::max<uint64_t>(1, modulus / clocks(rng));
    p.blocks.push_back(b);
  }
  return p;
}

std::vector<InterpOutputs> golden_trace(const std::vector<uint8_t>& frames, const InterpConfig& cfg,
                                        uint64_t cycles_per_frame, const GoldenInterp::Fault* fault,
                                        const std::vector<OperatorEvent>& events) {
  GoldenInterp dut(cfg);
  if (fault) dut.inject(*fault);
  FrameSource source(frames, cycles_per_frame, events);
  std::vector<InterpOutputs> trace;
  run_engine(dut, source, 50'000'000, [&](uint64_t, const InterpOutputs& o) { trace.push_back(o); });
  return trace;
}

}  // namespace ncinterp::checker::test
