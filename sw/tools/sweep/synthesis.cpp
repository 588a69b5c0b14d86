// Synthesis and place-and-route of the RTL at one width (see synthesis.h).
#include "synthesis.h"

#include <filesystem>
#include <sstream>

#include "file_lock.h"
#include "subprocess.h"
#include "synth_cache.h"
#include "synth_logs.h"

namespace ncinterp::sweep {
namespace {

std::string read_sources(const std::vector<std::string>& files) {
  std::string s = "read_verilog -sv";
  for (const std::string& f : files) s += " \"" + f + "\"";
  return s + "; ";
}

std::string chparams(const RtlParameters& params, const std::string& top) {
  std::string s;
  for (const auto& [name, value] : params) s += "chparam -set " + name + " " + std::to_string(value) + " " + top + "; ";
  return s;
}

// interp_top with these parameters through a yosys synthesis command ("synth" or
// "synth_ice40" with its options), then stat.
std::string stat_script(const SynthesisSetup& s, const RtlParameters& p, const std::string& synth) {
  return read_sources(s.rtl_sources) + chparams(p, "interp_top") + synth + " -top interp_top; stat";
}

std::string synth_ice40(const SynthesisSetup& s) { return "synth_ice40 " + s.synth_ice40_options; }

std::string harness_script(const SynthesisSetup& s, const RtlParameters& p, const std::string& json) {
  std::vector<std::string> files = s.rtl_sources;
  files.push_back(s.fpga_top);
  return read_sources(files) + chparams(p, "interp_fpga_top") + synth_ice40(s) + " -top interp_fpga_top -json \"" +
         json + "\"";
}

std::vector<std::string> pnr_command(const SynthesisSetup& s, const std::vector<std::string>& part,
                                     const std::string& json) {
  std::ostringstream freq;
  freq << s.pnr_target_mhz;
  std::vector<std::string> cmd = {s.nextpnr};
  cmd.insert(cmd.end(), part.begin(), part.end());
  // --timing-allow-fail: a design slower than the target still gets its Fmax measured.
  for (const std::string& a : {std::string("--json"), json, std::string("--freq"), freq.str(),
                               std::string("--seed"), std::to_string(s.pnr_seed),
                               std::string("--timing-allow-fail")})
    cmd.push_back(a);
  return cmd;
}

// Why a tool run gave no numbers: it did not start or was killed, or its log's first error.
std::string failure_reason(const std::string& what, const ProcessOutcome& p, const std::string& log) {
  if (!p.started || p.signal) return p.failure;
  const std::string error = first_error_line(read_text_file(log));
  return what + " failed: " + (error.empty() ? "exit code " + std::to_string(p.exit_code) : error);
}

// A tool run that did not start or was killed says nothing about the design: not cached.
bool completed(const ProcessOutcome& p) { return p.started && p.signal == 0; }

struct Placement {
  Measured logic_cells, fmax_mhz;
};

// nextpnr-ice40 on one part: logic cells and Fmax, or why not (too big, a failed run).
Placement place(const SynthesisSetup& s, const std::string& part_name, const std::vector<std::string>& part,
                const std::string& json, const std::string& log, bool& cacheable) {
  const ProcessOutcome p = run_process(pnr_command(s, part, json), log);
  cacheable &= completed(p);
  const NextpnrReport rep = completed(p) ? parse_nextpnr_log(read_text_file(log)) : NextpnrReport{};
  const bool too_big = rep.logic_cells && rep.logic_cells_available && *rep.logic_cells > *rep.logic_cells_available;
  // The reason for whatever is missing below.
  const std::string why = p.ok()    ? "nextpnr-ice40: no utilisation or \"Max frequency\" line in " + log
                          : too_big ? "too big for the " + part_name + ": " + std::to_string(*rep.logic_cells) + " of " +
                                          std::to_string(*rep.logic_cells_available) + " logic cells"
                                    : failure_reason("nextpnr-ice40", p, log);
  Placement r;
  r.logic_cells = rep.logic_cells ? Measured::of(static_cast<double>(*rep.logic_cells)) : Measured::absent(why);
  r.fmax_mhz = p.ok() && rep.fmax_mhz ? Measured::of(*rep.fmax_mhz) : Measured::absent(why);
  return r;
}

}  // namespace

std::string parameter_tag(const RtlParameters& params) {
  std::string tag;
  for (const auto& [name, value] : params)
    tag += (tag.empty() ? "" : "-") + (name == "IncWidth" ? std::string("w") : name) + std::to_string(value);
  return tag;
}

SynthResult synthesize(unsigned width, const SynthesisSetup& setup, const std::string& key) {
  return synthesize(RtlParameters{{"IncWidth", width}}, setup, key);
}

std::string synthesis_key(const SynthesisSetup& s) {
  std::vector<std::string> files = s.rtl_sources;
  files.push_back(s.fpga_top);
  std::vector<std::string> extra = pnr_command(s, s.pnr_part_args, "");
  if (!s.small_part_name.empty())
    for (const std::string& a : pnr_command(s, s.small_part_args, "")) extra.push_back(a);
  for (const std::string& script :
       {stat_script(s, {}, "synth"), stat_script(s, {}, synth_ice40(s)), harness_script(s, {}, "")})
    extra.push_back(script);
  for (const std::string& tool : {s.yosys, s.nextpnr}) {
    const std::string log = s.work_dir + "/" + std::filesystem::path(tool).filename().string() + ".version";
    std::filesystem::create_directories(s.work_dir);
    const ProcessOutcome p = run_process({tool, tool == s.yosys ? "-V" : "--version"}, log);
    extra.push_back(p.ok() ? read_text_file(log) : "missing " + tool);
  }
  return content_hash(files, extra);
}

SynthResult synthesize(const RtlParameters& w, const SynthesisSetup& s, const std::string& key) {
  const SynthCache cache(s.cache_dir, key);
  const std::string tag = parameter_tag(w);
  if (std::optional<SynthResult> hit = cache.load(tag)) return *hit;

  // One synthesis of a parameter set at a time (points sharing it may run at once): a
  // second one waits here and then takes the first's result from the cache.
  std::filesystem::create_directories(s.work_dir);
  const FileLock lock(s.work_dir + "/" + tag + ".lock");
  if (std::optional<SynthResult> hit = cache.load(tag)) return *hit;

  SynthResult r;
  const std::string dir = s.work_dir + "/" + tag;
  std::filesystem::create_directories(dir);
  bool cacheable = true;

  // Generic cells and flip-flops.
  {
    const std::string log = dir + "/yosys_synth.log";
    const ProcessOutcome p = run_process({s.yosys, "-p", stat_script(s, w, "synth")}, log);
    cacheable &= completed(p);
    const std::optional<YosysStat> stat = p.ok() ? parse_yosys_stat(read_text_file(log)) : std::nullopt;
    if (stat) {
      r.cells = Measured::of(static_cast<double>(stat->cells));
      r.flip_flops = Measured::of(static_cast<double>(stat->flip_flops()));
    } else {
      r.cells = r.flip_flops =
          Measured::absent(p.ok() ? "yosys synth: no statistics in " + log : failure_reason("yosys synth", p, log));
    }
  }
  // iCE40 LUTs of interp_top itself.
  {
    const std::string log = dir + "/yosys_synth_ice40.log";
    const ProcessOutcome p = run_process({s.yosys, "-p", stat_script(s, w, synth_ice40(s))}, log);
    cacheable &= completed(p);
    const std::optional<YosysStat> stat = p.ok() ? parse_yosys_stat(read_text_file(log)) : std::nullopt;
    r.ice40_luts = stat ? Measured::of(static_cast<double>(stat->count("SB_LUT4")))
                        : Measured::absent(p.ok() ? "synth_ice40: no statistics in " + log
                                                  : failure_reason("yosys synth_ice40", p, log));
  }
  // Placement and routing of the harness on the part: logic cells and Fmax.
  {
    const std::string json = dir + "/interp_fpga_top.json";
    const std::string ylog = dir + "/yosys_harness.log";
    const ProcessOutcome y = run_process({s.yosys, "-p", harness_script(s, w, json)}, ylog);
    cacheable &= completed(y);
    if (!y.ok()) {
      r.ice40_logic_cells = r.fmax_mhz = r.small_logic_cells = r.small_fmax_mhz =
          Measured::absent(failure_reason("yosys synth_ice40 (harness)", y, ylog));
    } else {
      const Placement big = place(s, s.pnr_part_name, s.pnr_part_args, json, dir + "/nextpnr.log", cacheable);
      r.ice40_logic_cells = big.logic_cells;
      r.fmax_mhz = big.fmax_mhz;
      r.small_logic_cells = r.small_fmax_mhz = Measured::absent("no small part placed");
      if (!s.small_part_name.empty()) {
        const Placement small =
            place(s, s.small_part_name, s.small_part_args, json, dir + "/nextpnr_small.log", cacheable);
        r.small_logic_cells = small.logic_cells;
        r.small_fmax_mhz = small.fmax_mhz;
      }
    }
  }
  if (cacheable) cache.store(tag, r);
  return r;
}

}  // namespace ncinterp::sweep
