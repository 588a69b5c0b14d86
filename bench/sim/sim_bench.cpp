// Simulation-speed benchmark of the interpolator engines (figures in docs/performance.md).
//
// What: plays one tape (default examples/gear.nc at 1 MHz with a 1000 cps reader, the CLI's
// defaults) in one arch (--arch, default serial) on each engine and reports simulated clock
// cycles per second:
//   golden            GoldenInterp + FrameSource (plain C++)
//   rtl               verilated RTL (the arch's model, rtl_models.h) with a C++ harness
//   rtl-trace-off     the arch's --trace build with tracing off
//   cosim             lock step: RTL + golden + every output compared every clock
//   rtl-vcd           the --trace build writing a VCD of every signal, every clock
//   icarus            the same RTL under Icarus Verilog (bench/sim/interp_tb.sv, $readmemh)
//   system-golden/rtl the SystemC system model (`ncinterp play --engine ...`)
// Idea: each in-process engine replays the tape from reset until it has used --seconds of
// CPU time; the rate is cycles / CPU seconds (the machine is shared, so CPU time is the
// fair measure; wall time is printed beside it). Every engine must end in the same state
// as the golden model (cycles and final position), else the benchmark fails.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "frame_source.h"
#include "interp_top.h"
#include "lockstep.h"
#include "machine_options.h"
#include "rtl_models.h"
#include "tape.h"
#include "verilated_interp.h"
#include "verilated_vcd_c.h"

namespace ncinterp::bench {
namespace {

namespace fs = std::filesystem;

struct Options {
  std::string tape = NCINTERP_DEFAULT_TAPE;
  Arch arch = Arch::kSerial;
  double clock_hz = 1e6;
  double reader_cps = 1000;
  double seconds = 2.0;             // CPU time per in-process engine
  uint64_t vcd_cycles = 1'000'000;  // cycles traced to a VCD
  uint64_t icarus_cycles = 2'000'000;
  std::string ncinterp = NCINTERP_EXE;
  std::string rtl_sources = NCINTERP_RTL_SOURCES;  // space-separated, package first
  std::string tb = NCINTERP_TB;
  bool skip_icarus = false, skip_system = false;
  std::vector<std::string> engines;  // empty: all
  bool wants(const std::string& e) const {
    return engines.empty() || std::find(engines.begin(), engines.end(), e) != engines.end();
  }
};

struct Row {
  std::string engine;
  uint64_t cycles = 0;
  double cpu_s = 0, wall_s = 0;
  std::string note;
  bool measured = true;
};

double cpu_now() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
double wall_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double children_cpu() {
  rusage u;
  getrusage(RUSAGE_CHILDREN, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct EndState {
  uint64_t cycles = 0;
  int64_t x = 0, y = 0;
  bool operator==(const EndState& o) const { return cycles == o.cycles && x == o.x && y == o.y; }
};

// Repeats `one_run` (a full replay of the tape from reset, returning its end state) until
// the CPU budget is used; checks every replay ends like `want`.
Row measure(const std::string& name, double budget, const EndState& want,
            const std::function<EndState()>& one_run) {
  Row row{name};
  const double c0 = cpu_now(), w0 = wall_now();
  do {
    const EndState e = one_run();
    if (!(e == want)) {
      std::ostringstream s;
      s << name << ": ended at cycle " << e.cycles << " (" << e.x << ", " << e.y
        << "), the golden model at " << want.cycles << " (" << want.x << ", " << want.y << ")";
      throw std::runtime_error(s.str());
    }
    row.cycles += e.cycles;
  } while (cpu_now() - c0 < budget);
  row.cpu_s = cpu_now() - c0;
  row.wall_s = wall_now() - w0;
  return row;
}

// The golden model's harness reads its output registers in place, the outputs it needs
// per clock (as play_rtl below): a copy of the whole output struct per clock would stall
// on the model's byte stores of step_x / step_y and cost about a tenth of the golden row.
EndState play(GoldenInterp& dut, const std::vector<uint8_t>& frames, uint64_t cpf, uint64_t max_cycles) {
  FrameSource source(frames, cpf);
  uint64_t cycle = 0;
  const InterpOutputs& o = dut.outputs();
  while (!o.done && !o.error && cycle < max_cycles) {
    const bool ready = o.frame_ready;
    dut.tick(source.inputs());
    source.clock(ready);
    ++cycle;
  }
  return {cycle, o.pos_x, o.pos_y};
}

// The verilated harness reads only the two outputs it needs per clock (as a testbench
// would), the final position at the end.
template <class Model>
EndState play_rtl(VerilatedInterp<Model>& rtl, const std::vector<uint8_t>& frames, uint64_t cpf,
                  uint64_t max_cycles, VerilatedVcdC* vcd = nullptr, uint64_t period = 2) {
  FrameSource source(frames, cpf);
  uint64_t cycle = 0;
  Model& m = rtl.model();
  while (!m.done_o && !m.error_o && cycle < max_cycles) {
    const bool ready = m.frame_ready_o;
    ++cycle;
    if (vcd) {
      rtl.tick(source.inputs(), [&](int phase) { vcd->dump(cycle * period - (phase ? 0 : period / 2)); });
    } else {
      rtl.tick(source.inputs());
    }
    source.clock(ready);
  }
  return {cycle, static_cast<int32_t>(m.pos_x_o), static_cast<int32_t>(m.pos_y_o)};
}

int run_command(const std::string& cmd, std::string* output) {
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return -1;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) output->append(buf, n);
  const int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

Row measure_icarus(const Options& o, const std::vector<uint8_t>& frames, uint64_t cpf,
                   const InterpConfig& cfg, const fs::path& work) {
  Row row{"icarus"};
  const fs::path hex = work / "frames.hex", vvp = work / "interp_tb.vvp";
  {
    std::ofstream out(hex);
    char line[8];
    for (uint8_t f : frames) {
      std::snprintf(line, sizeof line, "%02x\n", f);
      out << line;
    }
  }
  std::string log;
  const std::string compile = "iverilog -g2012 -Pinterp_tb.BitSerial=" +
                              std::string(cfg.serial() ? "1" : "0") + " -o " + vvp.string() + " " + o.rtl_sources + " " +
                              o.tb + " 2>&1";
  if (run_command(compile, &log) != 0) throw std::runtime_error("iverilog failed:\n" + log);
  std::ostringstream cmd;
  cmd << "vvp -n " << vvp.string() << " +frames=" << hex.string() << " +nframes=" << frames.size()
      << " +cpf=" << cpf << " +modulus=" << cfg.feed_modulus << " +rapid=" << cfg.rapid_step
      << " +max_cycles=" << o.icarus_cycles;
  std::string out;
  const double c0 = children_cpu(), w0 = wall_now();
  if (run_command(cmd.str(), &out) != 0) throw std::runtime_error("vvp failed:\n" + out);
  row.wall_s = wall_now() - w0;
  row.cpu_s = children_cpu() - c0;
  long long cycles = 0, x = 0, y = 0;
  const auto at = out.find("cycles ");
  if (at == std::string::npos ||
      std::sscanf(out.c_str() + at, "cycles %lld pos %lld %lld", &cycles, &x, &y) != 3)
    throw std::runtime_error("icarus: unexpected output:\n" + out);
  row.cycles = static_cast<uint64_t>(cycles);
  // The same number of clocks on the golden model must end at the same position.
  GoldenInterp golden(cfg);
  const EndState g = play(golden, frames, cpf, row.cycles);
  if (g.cycles != row.cycles || g.x != x || g.y != y)
    throw std::runtime_error("icarus disagrees with the golden model after " +
                             std::to_string(cycles) + " cycles");
  row.note = "vvp wall time incl. start-up; " + std::to_string(cycles) + " cycles";
  return row;
}

Row measure_system(const Options& o, const std::string& engine, const EndState& want,
                   const fs::path& work) {
  Row row{"system-" + engine};
  const fs::path report = work / ("play_" + engine + ".json");
  std::ostringstream cmd;
  cmd << o.ncinterp << " play " << o.tape << " --engine " << engine << " --arch "
      << arch_name(o.arch) << " --clock-hz " << o.clock_hz
      << " --reader-cps " << o.reader_cps << " --report " << report.string() << " 2>&1";
  std::string out;
  const double c0 = children_cpu();
  if (run_command(cmd.str(), &out) != 0) throw std::runtime_error("ncinterp play failed:\n" + out);
  row.cpu_s = children_cpu() - c0;
  std::ifstream in(report);
  const nlohmann::json j = nlohmann::json::parse(in);
  row.cycles = j.at("cycles").get<uint64_t>();
  row.wall_s = j.at("wall_seconds").get<double>();
  const EndState e{row.cycles, j.at("final_position_blu").at("x").get<int64_t>(),
                   j.at("final_position_blu").at("y").get<int64_t>()};
  if (!(e == want)) throw std::runtime_error(row.engine + " ends differently from the golden model");
  row.note = "`ncinterp play`: run_play wall time; CPU incl. process start";
  return row;
}

int run(const Options& o) {
  const std::vector<uint8_t> frames = tape::load_frames(o.tape);
  InterpConfig cfg;
  cfg.arch = o.arch;
  cfg.feed_modulus = InterpConfig::feed_modulus_for(o.clock_hz, cfg.feed_frac_digits);
  const uint64_t cpf = FrameSource::cycles_per_frame_for(o.clock_hz, o.reader_cps);
  const uint64_t limit = 50'000'000'000ull;
  const fs::path work = fs::temp_directory_path() / ("ncinterp_sim_bench_" + std::to_string(getpid()));
  fs::create_directories(work);
  struct Cleanup {
    fs::path p;
    ~Cleanup() { std::error_code ec; fs::remove_all(p, ec); }
  } cleanup{work};

  GoldenInterp reference(cfg);
  const EndState want = play(reference, frames, cpf, limit);
  if (!reference.outputs().done) throw std::runtime_error(o.tape + ": the program does not play to done");

  std::vector<Row> rows;
  if (o.wants("golden"))
    rows.push_back(measure("golden", o.seconds, want, [&] {
      GoldenInterp g(cfg);
      return play(g, frames, cpf, limit);
    }));
  if (o.wants("rtl"))
    rows.push_back(measure("rtl", o.seconds, want, [&] {
      return with_rtl_model(cfg.arch, [&](auto model) {
        VerilatedInterp<typename decltype(model)::type> rtl(cfg, rtl_built_config(cfg.arch));
        return play_rtl(rtl, frames, cpf, limit);
      });
    }));
  if (o.wants("rtl-trace-off"))
    rows.push_back(measure("rtl-trace-off", o.seconds, want, [&] {
      return with_rtl_trace_model(cfg.arch, [&](auto model) {
        VerilatedInterp<typename decltype(model)::type> rtl(cfg, rtl_built_config(cfg.arch));
        return play_rtl(rtl, frames, cpf, limit);
      });
    }));
  cosim::Options co;
  co.config = cfg;
  co.cycles_per_frame = cpf;
  co.max_cycles = limit;
  if (o.wants("cosim"))
    rows.push_back(measure("cosim", o.seconds, want, [&] {
      const cosim::Result r = cosim::run_lockstep(frames, co);
      if (r.mismatch) throw std::runtime_error("cosim: " + cosim::describe(*r.mismatch));
      return EndState{r.cycles, r.last.pos_x, r.last.pos_y};
    }));
  if (o.wants("rtl-vcd")) {
    // VCD of every signal for the first vcd_cycles clocks (compare with the golden model
    // stopped at the same clock).
    GoldenInterp g(cfg);
    const EndState part = play(g, frames, cpf, o.vcd_cycles);
    const fs::path vcd_path = work / "bench.vcd";
    Row row = measure("rtl-vcd", 0.0, part, [&] {
      return with_rtl_trace_model(cfg.arch, [&](auto model) {
        VerilatedInterp<typename decltype(model)::type> rtl(cfg, rtl_built_config(cfg.arch));
        rtl.context().traceEverOn(true);
        VerilatedVcdC vcd;
        rtl.model().trace(&vcd, 99);
        vcd.open(vcd_path.string().c_str());
        const EndState e = play_rtl(rtl, frames, cpf, o.vcd_cycles, &vcd,
                                    static_cast<uint64_t>(1e12 / o.clock_hz));
        vcd.close();
        return e;
      });
    });
    std::ostringstream note;
    note << "all signals; " << fs::file_size(vcd_path) / row.cycles << " bytes/cycle";
    row.note = note.str();
    rows.push_back(row);
  }
  if (!o.skip_icarus && o.wants("icarus")) rows.push_back(measure_icarus(o, frames, cpf, cfg, work));
  for (const char* engine : {"golden", "rtl"}) {
    if (!o.wants(std::string("system-") + engine)) continue;
    if (o.skip_system || !fs::exists(o.ncinterp)) {
      rows.push_back(Row{std::string("system-") + engine, 0, 0, 0, "not measured (no ncinterp)", false});
    } else {
      rows.push_back(measure_system(o, engine, want, work));
    }
  }

  std::printf("tape %s, %s arch: %zu frames, %llu cycles per run at %g Hz, reader %g cps (%llu "
              "cycles/frame)\n\n",
              o.tape.c_str(), arch_name(o.arch), frames.size(), static_cast<unsigned long long>(want.cycles),
              o.clock_hz, o.reader_cps, static_cast<unsigned long long>(cpf));
  // The rate as a ratio to the golden model's of the same run: the machine's speed cancels.
  const auto cpu_rate = [](const Row& r) { return r.cpu_s > 0 ? r.cycles / r.cpu_s / 1e6 : 0.0; };
  double golden_rate = 0;
  for (const Row& r : rows)
    if (r.measured && r.engine == "golden") golden_rate = cpu_rate(r);
  std::printf("| engine | cycles | CPU s | wall s | M cycles/s (CPU) | M cycles/s (wall) | / golden (CPU) | note |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---|\n");
  for (const Row& r : rows) {
    if (!r.measured) {
      std::printf("| %s | | | | | | | %s |\n", r.engine.c_str(), r.note.c_str());
      continue;
    }
    std::string ratio;
    if (golden_rate > 0) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3f", cpu_rate(r) / golden_rate);
      ratio = buf;
    }
    std::printf("| %s | %llu | %.2f | %.2f | %.2f | %.2f | %s | %s |\n", r.engine.c_str(),
                static_cast<unsigned long long>(r.cycles), r.cpu_s, r.wall_s, cpu_rate(r),
                r.wall_s > 0 ? r.cycles / r.wall_s / 1e6 : 0.0, ratio.c_str(), r.note.c_str());
  }
  return 0;
}

}  // namespace
}  // namespace ncinterp::bench

int main(int argc, char** argv) {
  ncinterp::bench::Options o;
  CLI::App app{"Simulation speed of the interpolator engines (docs/performance.md)"};
  app.add_option("--tape", o.tape, "tape to play")->capture_default_str();
  ncinterp::cli::add_arch_option(&app, o.arch);
  app.add_option("--clock-hz", o.clock_hz, "interpolator clock, Hz")->capture_default_str();
  app.add_option("--reader-cps", o.reader_cps, "tape reader, characters per second")->capture_default_str();
  app.add_option("--seconds", o.seconds, "CPU seconds per in-process engine")->capture_default_str();
  app.add_option("--vcd-cycles", o.vcd_cycles, "cycles traced to the VCD")->capture_default_str();
  app.add_option("--icarus-cycles", o.icarus_cycles, "cycles simulated by Icarus")->capture_default_str();
  app.add_option("--ncinterp", o.ncinterp, "ncinterp executable (system model rows)")->capture_default_str();
  app.add_option("--engines", o.engines,
                 "only these rows: golden rtl rtl-trace-off cosim rtl-vcd icarus system-golden system-rtl")
      ->delimiter(',');
  app.add_flag("--skip-icarus", o.skip_icarus, "do not run Icarus Verilog");
  app.add_flag("--skip-system", o.skip_system, "do not run the SystemC system model");
  CLI11_PARSE(app, argc, argv);
  try {
    return ncinterp::bench::run(o);
  } catch (const std::exception& e) {
    std::cerr << "sim_bench: " << e.what() << "\n";
    return 1;
  }
}
