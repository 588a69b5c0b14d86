// `ncinterp methods`: the reference-word interpolators of paper 003 (L1, K1..K7) measured
// against the paper's error claims and compared with the hardware circle DDA
// (docs/sampled-data.md). Without --h it sweeps h from 1e-4 to 1e-1 over radii 1, 10 and
// 100 mm; --radius and --h pick one of each. Prints the tables; --csv and --svg are written
// only after everything has been computed (atomically). Exit 0, or 1 with one line on
// stderr and no file written.
#include <cmath>
#include <iostream>
#include <memory>

#include "output_set.h"
#include "progress.h"
#include "command_registry.h"
#include "dda_comparison.h"
#include "interp_ports.h"
#include "method_study.h"
#include "methods_plot.h"
#include "methods_report.h"

namespace ncinterp::cli {
namespace {

struct MethodsArgs {
  double radius_mm = 0;  // 0: the default radii
  double h = 0;          // 0: the default sweep
  int turns = 10;
  int word_bits = 32;
  std::string start = "k7";
  std::string csv, svg;
};

void run(const MethodsArgs& a) {
  // Every output reserved before the study (a bad path fails now; a failure leaves none).
  OutputSet outputs;
  AtomicOutputFile* csv_out = outputs.add(a.csv);
  AtomicOutputFile* svg_out = outputs.add(a.svg);
  sampled::StudyConfig cfg;
  cfg.radii_mm = a.radius_mm > 0 ? std::vector<double>{a.radius_mm} : sampled::default_radii_mm();
  cfg.hs = a.h > 0 ? std::vector<double>{a.h} : sampled::default_h_sweep();
  cfg.turns = a.turns;
  cfg.word_bits = a.word_bits;
  cfg.starter = *sampled::parse_starter(a.start);
  Progress progress("methods");
  if (progress.enabled())
    cfg.progress = [&progress](size_t done, size_t total) {
      progress.show(std::to_string(done) + " of " + std::to_string(total) + " runs");
    };

  // The hardware DDA works in BLU of the interpolator's default tape format.
  const double blu_mm = std::pow(10.0, -static_cast<double>(InterpConfig{}.frac_digits));
  std::vector<int64_t> radii_blu;
  for (double r : cfg.radii_mm) radii_blu.push_back(std::llround(r / blu_mm));

  const sampled::Study study = sampled::run_study(cfg);
  progress.clear();
  const auto comparison = sampled::compare_with_hardware_dda(radii_blu, cfg.starter);
  const std::string text = sampled::methods_text(study, comparison, blu_mm);
  if (csv_out) OutputSet::write(csv_out, sampled::methods_csv(study));
  if (svg_out) OutputSet::write(svg_out, sampled::methods_svg(study));
  outputs.commit();
  std::cout << text;
}

CommandRegistration registration("methods", [](CLI::App& app) {
  auto args = std::make_shared<MethodsArgs>();
  CLI::App* cmd = app.add_subcommand(
      "methods", "measure the reference-word interpolators L1, K1..K7 of paper 003 against its error claims");
  cmd->add_option("--radius", args->radius_mm, "one circle radius (and line length), mm (default: 1, 10 and 100)")
      ->check(CLI::Range(0.001, 1000.0));
  cmd->add_option("--h", args->h, "one step h = V T / R, radian per period (default: 1e-4 .. 1e-1)")
      ->check(CLI::Range(1e-5, 0.5));
  cmd->add_option("--turns", args->turns, "turns run for the drift")->check(CLI::Range(2, 1000))->capture_default_str();
  cmd->add_option("--word-bits", args->word_bits, "fixed-point word length B, sign included")
      ->check(CLI::Range(8, 62))
      ->capture_default_str();
  cmd->add_option("--start", args->start, "the period K2 and K3 start with (they are not self-starting)")
      ->check(CLI::IsMember({"k1", "k7"}))
      ->capture_default_str();
  cmd->add_option("--csv", args->csv, "every measured row (method, radius, h, errors, ...)");
  cmd->add_option("--svg", args->svg, "error against h on log axes, one curve per method");
  cmd->callback([args]() {
    try {
      run(*args);
    } catch (const std::exception& e) {
      std::cerr << "ncinterp methods: " << e.what() << "\n";
      throw CommandExit{1};
    }
  });
});

}  // namespace
}  // namespace ncinterp::cli
