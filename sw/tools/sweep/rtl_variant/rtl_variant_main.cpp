// ncinterp_rtl_variant: the lock-step cosim (sc_model/cosim/lockstep_loop.h) of one variant
// of the RTL (verilated with -GIncWidth=W -GFracDigits=D -GBitSerial=B) against the golden
// model with the same parameters.
// Usage: ncinterp_rtl_variant [--clock-hz F] [--reader-cps C] TAPE...   (.tape frames)
// Prints one line per tape, "done CYCLES TAPE" when both engines agreed on every clock up
// to the end of the program, else "mismatch|error|cycle_limit CYCLES TAPE: detail".
// Exit 0 when every tape ran to its end in agreement, 2 otherwise, 1 on bad arguments.
// Built on demand by the sweep (sw/tools/sweep/rtl_variant.cpp); see CMakeLists.txt here.
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "Vinterp_top.h"
#include "frame_source.h"
#include "lockstep_loop.h"
#include "verilated_interp.h"

namespace {

std::vector<uint8_t> read_frames(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ncinterp;
  double clock_hz = 1e6, reader_cps = 1000.0;
  std::vector<std::string> tapes;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if ((a == "--clock-hz" || a == "--reader-cps") && i + 1 < argc)
        (a == "--clock-hz" ? clock_hz : reader_cps) = std::stod(argv[++i]);
      else if (a.rfind("--", 0) == 0)
        throw std::invalid_argument("unknown option " + a);
      else
        tapes.push_back(a);
    }
    if (tapes.empty() || !(clock_hz > 0) || !(reader_cps > 0))
      throw std::invalid_argument("usage: ncinterp_rtl_variant [--clock-hz F] [--reader-cps C] TAPE...");
  } catch (const std::exception& e) {
    std::cerr << "ncinterp_rtl_variant: " << e.what() << "\n";
    return 1;
  }

  cosim::Options options;
  options.config.inc_width = NCINTERP_RTL_INC_WIDTH;
  options.config.frac_digits = NCINTERP_RTL_FRAC_DIGITS;
  options.config.arch = NCINTERP_RTL_BIT_SERIAL ? Arch::kSerial : Arch::kParallel;
  options.config.circle_mode = NCINTERP_RTL_CIRCLE_MODE;
  const InterpConfig built = options.config;
  options.config.feed_modulus = InterpConfig::feed_modulus_for(clock_hz, options.config.feed_frac_digits);
  options.cycles_per_frame = FrameSource::cycles_per_frame_for(clock_hz, reader_cps);
  int code = 0;
  for (const std::string& tape : tapes) {
    try {
      VerilatedInterp<Vinterp_top> rtl(options.config, built);
      const cosim::Result r = cosim::run_lockstep_on(rtl, read_frames(tape), options);
      switch (r.end) {
        case cosim::Result::End::kDone: std::cout << "done " << r.cycles << " " << tape << "\n"; break;
        case cosim::Result::End::kMismatch:
          std::cout << "mismatch " << r.cycles << " " << tape << ": " << cosim::describe(*r.mismatch) << "\n";
          break;
        case cosim::Result::End::kTapeError:
          std::cout << "error " << r.cycles << " " << tape << ": tape error code "
                    << int(r.last.error_code) << " at block N" << r.last.error_block << "\n";
          break;
        case cosim::Result::End::kCycleLimit:
          std::cout << "cycle_limit " << r.cycles << " " << tape << ": no end of program\n";
          break;
      }
      if (r.end != cosim::Result::End::kDone) code = 2;
    } catch (const std::exception& e) {
      std::cout << "error 0 " << tape << ": " << e.what() << "\n";
      code = 2;
    }
  }
  return code;
}
