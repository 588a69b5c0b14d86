// The verilated floor: how fast Verilator clocks the one part of the interpolator that
// works on every clock, the feed generator's phase (rtl/feed_generator.sv), alone.
//
// What: feed_generator verilated with the interpolator's Verilator switches, clocked the
// way VerilatedInterp clocks interp_top (set the inputs, eval with clk low, eval with clk
// high), with a block loaded and running; prints M clocks/s of CPU time
// (docs/performance.md).
// Idea: an idle clock of the interpolator advances the phase and nothing else (the golden
// model's tick() does only that), but a verilated model evaluates all of its logic, and
// Verilator's scheduler, twice per clock. A model of the phase alone bounds what any
// verilated interp_top can reach on the same machine: sim_bench's rtl row over this
// figure is how much of that ceiling the whole design keeps.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <ctime>

#include "Vfeed_generator.h"
#include "verilated.h"

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

void clock(Vfeed_generator& m) {
  m.clk_i = 0;
  m.eval();
  m.clk_i = 1;
  m.eval();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Verilated floor: rtl/feed_generator.sv alone, clocked like sim_bench's rtl row"};
  double seconds = 2.0;
  app.add_option("--seconds", seconds, "CPU time to run")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

  VerilatedContext context;
  Vfeed_generator m(&context);
  // The CLI's defaults: 1 MHz, so M = 60 * 10^6 * 10^3; S = M / 50 gives a strobe every
  // 50 clocks (the rate does not matter: the model evaluates the same logic every clock).
  constexpr uint64_t kModulus = 60'000'000'000ULL;
  constexpr uint64_t kClocksPerStrobe = 50;
  m.modulus_i = kModulus;
  m.rst_ni = 0;
  clock(m);
  m.rst_ni = 1;
  m.step_i = kModulus / kClocksPerStrobe;
  m.run_step_i = kModulus / kClocksPerStrobe;
  m.load_i = 1;
  clock(m);
  m.load_i = 0;
  m.run_i = 1;

  constexpr uint64_t kBatch = 1'000'000;
  uint64_t clocks = 0, strobes = 0;
  const double start = cpu_seconds();
  double used = 0;
  do {
    for (uint64_t i = 0; i < kBatch; ++i) {
      clock(m);
      strobes += m.strobe_o;
    }
    clocks += kBatch;
    used = cpu_seconds() - start;
  } while (used < seconds);
  // The strobes show that the model really ran (and keep the compiler from dropping it).
  if (strobes != clocks / kClocksPerStrobe) {
    std::fprintf(stderr, "verilator_floor: %llu strobes in %llu clocks, expected one per %llu\n",
                 static_cast<unsigned long long>(strobes), static_cast<unsigned long long>(clocks),
                 static_cast<unsigned long long>(kClocksPerStrobe));
    return 1;
  }
  std::printf("feed_generator alone: %llu clocks in %.2f s of CPU: %.1f M clocks/s\n",
              static_cast<unsigned long long>(clocks), used, double(clocks) / used * 1e-6);
  return 0;
}
