// The sweep over widths on a thread pool (see sweep_run.h).
#include "sweep_run.h"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <mutex>
#include <thread>

namespace ncinterp::sweep {
namespace {

SynthResult synth_not_run(const std::string& why) {
  SynthResult r;
  r.cells = r.flip_flops = r.ice40_luts = r.ice40_logic_cells = r.fmax_mhz = Measured::absent(why);
  return r;
}

// The row of one width (what each worker runs); synth_key from synthesis_key().
SweepRow sweep_width(unsigned w, const SweepSetup& setup, const std::string& synth_key,
                     const std::function<void(const std::string&)>& stage) {
  auto say = [&stage](const char* what) {
    if (stage) stage(what);
  };
  SweepRow row;
  row.width = w;

  say("first stage, golden model, checker");
  std::string tapes;
  if (setup.rtl) {
    tapes = setup.tape_dir + "/w" + std::to_string(w);
    std::error_code ec;
    std::filesystem::create_directories(tapes, ec);
  }
  std::vector<std::string> tape_paths;
  for (size_t i = 0; i < setup.inputs.size(); ++i) {
    const std::string name = std::to_string(i) + "_" + std::filesystem::path(setup.inputs[i].path).stem().string();
    const std::string tape = setup.rtl ? tapes + "/" + name + ".tape" : "";
    row.inputs.push_back(measure_input(setup.inputs[i], w, setup.measure, tape));
    if (!row.inputs.back().tape_path.empty()) tape_paths.push_back(row.inputs.back().tape_path);
  }

  if (setup.synthesis) {
    say("synthesis, place and route");
    try {
      row.synth = synthesize(w, setup.synth, synth_key);
    } catch (const std::exception& e) {
      row.synth = synth_not_run(std::string("synthesis: ") + e.what());
    }
  } else {
    row.synth = synth_not_run("not run (--no-synth)");
  }

  if (setup.rtl) {
    say("RTL variant: build and lock-step cosim");
    try {
      row.rtl = run_rtl_variant(setup.rtl_variant, w, tape_paths);
    } catch (const std::exception& e) {
      row.rtl.summary = std::string("RTL variant: ") + e.what();
    }
  } else {
    row.rtl.summary = "not run (--no-rtl)";
  }
  return row;
}

}  // namespace

std::vector<SweepRow> run_sweep(const SweepSetup& setup, const ProgressCallback& progress) {
  const size_t total = setup.widths.count();
  const std::string key = setup.synthesis ? synthesis_key(setup.synth) : "";
  std::vector<SweepRow> rows(total);
  std::atomic<size_t> next{0};
  std::mutex progress_mutex;
  size_t done = 0;
  auto report = [&](unsigned w, const std::string& stage, bool finished) {
    if (!progress && !finished) return;
    std::lock_guard<std::mutex> lock(progress_mutex);
    if (finished) ++done;
    if (progress) progress({w, stage, done, total});
  };
  auto worker = [&]() {
    for (size_t i = next++; i < total; i = next++) {
      const unsigned w = setup.widths.low + static_cast<unsigned>(i);
      rows[i] = sweep_width(w, setup, key, [&](const std::string& stage) { report(w, stage, false); });
      report(w, "done", true);
    }
  };
  unsigned jobs = setup.jobs ? setup.jobs : std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(std::min<size_t>(jobs, total));
  std::vector<std::thread> pool;
  for (unsigned j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();  // the calling thread is one of the workers
  for (std::thread& t : pool) t.join();
  return rows;
}

}  // namespace ncinterp::sweep
