// Building and running a width variant of the verilated RTL (see rtl_variant.h).
#include "rtl_variant.h"

#include <filesystem>
#include <sstream>

#include "subprocess.h"
#include "synth_logs.h"

namespace ncinterp::sweep {
namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (const std::string& i : items) s += (s.empty() ? "" : ";") + i;
  return s;
}

std::string build_dir(const RtlVariantSetup& s, const RtlVariant& v) {
  return s.build_root + "/w" + std::to_string(v.width) + "-d" + std::to_string(v.frac_digits) + "-" +
         arch_name(v.arch) + (v.circle_mode ? "" : "-lines");
}

std::string step_failure(const std::string& what, const ProcessOutcome& p, const std::string& log) {
  if (!p.started || p.signal) return what + ": " + p.failure;
  const std::string error = first_error_line(read_text_file(log));
  return what + " failed (" + log + ")" + (error.empty() ? "" : ": " + error);
}

}  // namespace

std::string RtlVariant::name() const {
  return "W=" + std::to_string(width) + " D=" + std::to_string(frac_digits) + " " + arch_name(arch) +
         (circle_mode ? "" : " lines");
}

std::string rtl_variant_executable(const RtlVariantSetup& s, const RtlVariant& v) {
  return build_dir(s, v) + "/ncinterp_rtl_variant";
}

std::string build_rtl_variant(const RtlVariantSetup& s, const RtlVariant& v) {
  const std::string dir = build_dir(s, v);
  std::filesystem::create_directories(dir);
  std::vector<std::string> configure = {s.cmake, "-S", s.project_dir, "-B", dir, "-DCMAKE_BUILD_TYPE=Release"};
  if (!s.generator.empty()) configure.insert(configure.end(), {"-G", s.generator});
  if (!s.cxx_compiler.empty()) configure.push_back("-DCMAKE_CXX_COMPILER=" + s.cxx_compiler);
  for (const std::string& d : {"INC_WIDTH=" + std::to_string(v.width),
                               "FRAC_DIGITS=" + std::to_string(v.frac_digits),
                               std::string("BIT_SERIAL=") + (v.arch == Arch::kSerial ? "ON" : "OFF"),
                               std::string("CIRCLE_MODE=") + (v.circle_mode ? "ON" : "OFF"),
                               "NCINTERP_SOURCE_DIR=" + s.source_dir, "RTL_SOURCES=" + joined(s.rtl_sources),
                               "VERILATOR_ARGS=" + joined(s.verilator_args), "GOLDEN_LIBRARY=" + s.golden_library})
    configure.push_back("-D" + d);
  const std::string configure_log = dir + "/configure.log";
  const ProcessOutcome c = run_process(configure, configure_log);
  if (!c.ok()) return step_failure("configuring the " + v.name() + " variant", c, configure_log);
  // One compile job per variant: the sweep already runs one width per core.
  const std::string build_log = dir + "/build.log";
  const ProcessOutcome b = run_process({s.cmake, "--build", dir, "--parallel", "1"}, build_log);
  if (!b.ok()) return step_failure("building the " + v.name() + " variant", b, build_log);
  return "";
}

RtlResult run_rtl_variant(const RtlVariantSetup& s, const RtlVariant& v, const std::vector<std::string>& tapes,
                          std::vector<std::string>* lines) {
  RtlResult r;
  if (tapes.empty()) {
    r.summary = "not run: no tape at this width";
    return r;
  }
  const std::string failure = build_rtl_variant(s, v);
  if (!failure.empty()) {
    r.summary = failure;
    return r;
  }
  std::ostringstream clock, reader;
  clock << s.clock_hz;
  reader << s.reader_cps;
  std::vector<std::string> cmd = {rtl_variant_executable(s, v), "--clock-hz", clock.str(), "--reader-cps", reader.str()};
  cmd.insert(cmd.end(), tapes.begin(), tapes.end());
  const std::string log = build_dir(s, v) + "/cosim.log";
  const ProcessOutcome p = run_process(cmd, log);
  r.ran = p.started;
  // One line per tape: "done CYCLES TAPE" or "mismatch|error|cycle_limit CYCLES TAPE: why".
  std::istringstream text(read_text_file(log));
  size_t done = 0;
  uint64_t cycles = 0;
  std::string first_problem;
  for (std::string line; std::getline(text, line);) {
    if (lines && !line.empty()) lines->push_back(line);
    std::istringstream in(line);
    std::string end;
    uint64_t c = 0;
    in >> end >> c;
    if (end == "done") {
      ++done;
      cycles += c;
    } else if (first_problem.empty() && !line.empty()) {
      first_problem = line;
    }
  }
  r.all_match = p.ok() && done == tapes.size();
  if (r.all_match)
    r.summary = "match on " + std::to_string(done) + " tapes, " + std::to_string(cycles) + " clocks";
  else if (!first_problem.empty())
    r.summary = first_problem;
  else
    r.summary = step_failure("the " + v.name() + " cosim", p, log);
  return r;
}

}  // namespace ncinterp::sweep
