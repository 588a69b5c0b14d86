// One design point measured (see point_run.h).
#include "point_run.h"

#include <chrono>
#include <cmath>
#include <filesystem>

#include "synth_cache.h"

namespace ncinterp::sweep {
namespace {

// The names the tools take from a point; anything else goes to the RTL as it is.
bool tool_parameter(const std::string& name) {
  return name == kIncWidth || name == kFeedWidth || name == kPosWidth || name == kBlu || name == kClock;
}

unsigned frac_digits_of(double blu_mm) { return static_cast<unsigned>(std::lround(-std::log10(blu_mm))); }

SynthResult synth_not_run(const std::string& why) {
  SynthResult r;
  r.cells = r.flip_flops = r.ice40_luts = r.ice40_logic_cells = r.fmax_mhz = r.small_logic_cells =
      r.small_fmax_mhz = Measured::absent(why);
  return r;
}

// The measurement setup of the point: the defaults with the point's values.
MeasureSetup measure_setup(const DesignPoint& p, const MeasureSetup& defaults) {
  MeasureSetup m = defaults;
  m.first_stage.width = static_cast<unsigned>(point_value(p, kIncWidth, defaults.first_stage.width));
  m.first_stage.feed_width = static_cast<unsigned>(point_value(p, kFeedWidth, defaults.first_stage.feed_width));
  m.first_stage.blu_mm = point_value(p, kBlu, defaults.first_stage.blu_mm);
  m.clock_hz = point_value(p, kClock, defaults.clock_hz);
  m.pos_width = static_cast<unsigned>(point_value(p, kPosWidth, defaults.pos_width));
  m.arch = point_value(p, kBitSerial, defaults.arch == Arch::kSerial ? 1 : 0) != 0 ? Arch::kSerial
                                                                                   : Arch::kParallel;
  m.circle_mode = point_value(p, kCircleMode, 1) != 0;
  if (!m.circle_mode) m.first_stage.arcs_circle = false;
  return m;
}

// The lock-step RTL variants are verilated with IncWidth, FracDigits, BitSerial and
// CircleMode (rtl_variant.h): a point that sets any other RTL parameter has no variant.
std::string rtl_variant_refusal(const DesignPoint& p, const MeasureSetup& defaults) {
  for (const auto& [name, value] : p) {
    if (name == kIncWidth || name == kClock || name == kBlu || name == kBitSerial || name == kCircleMode) continue;
    const bool is_default = (name == kFeedWidth && value == defaults.first_stage.feed_width) ||
                            (name == kPosWidth && value == defaults.pos_width);
    if (!is_default)
      return "not run (the RTL variants vary IncWidth, BLU, the arch and CircleMode only; " + name + "=" + value_text(value) + ")";
  }
  return "";
}

}  // namespace

RegisterRanges register_ranges(const DesignPoint& p, const MeasureSetup& defaults) {
  const MeasureSetup m = measure_setup(p, defaults);
  const double blu = m.first_stage.blu_mm;
  const double f_unit = 1e-3;  // F in 10^-3 1/min (FeedFracDigits 3)
  RegisterRanges r;
  r.max_move_mm = (std::ldexp(1.0, static_cast<int>(m.first_stage.width)) - 1.0) * blu;
  r.pos_range_mm = (std::ldexp(1.0, static_cast<int>(m.pos_width) - 1) - 1.0) * blu;
  r.feed_min_mm_min = f_unit * blu;
  r.feed_max_mm_min = (std::ldexp(1.0, static_cast<int>(m.first_stage.feed_width)) - 1.0) * f_unit * blu;
  r.feed_max_clock_mm_min = 60.0 * m.clock_hz * blu;
  return r;
}

RtlParameters rtl_parameters(const DesignPoint& p) {
  RtlParameters r;
  for (const char* name : {kIncWidth, kFeedWidth, kPosWidth})
    if (p.count(name)) r.emplace_back(name, std::llround(p.at(name)));
  if (p.count(kBlu)) r.emplace_back("FracDigits", frac_digits_of(p.at(kBlu)));
  for (const auto& [name, value] : p)
    if (!tool_parameter(name)) r.emplace_back(name, std::llround(value));
  return r;
}

std::string setup_hash(const PointSetup& s, const std::vector<std::string>& settings,
                       const std::vector<std::string>& model_sources) {
  std::vector<std::string> files;
  for (const SweepInput& in : s.inputs) files.push_back(in.path);
  files.insert(files.end(), model_sources.begin(), model_sources.end());
  std::vector<std::string> extra = settings;
  extra.push_back(s.synthesis ? "synthesis " + s.synth_key : "no synthesis");
  if (s.rtl)
    for (const std::string& f : s.rtl_variant.rtl_sources) extra.push_back("rtl " + content_hash({f}, {}));
  else
    extra.push_back("no rtl");
  return content_hash(files, extra);
}

std::string point_key(const DesignPoint& p, const std::string& setup_hash) {
  return content_hash({}, {setup_hash, point_text(p)});
}

PointResult run_point(const DesignPoint& p, const std::string& key, const PointSetup& setup,
                      const std::function<void(const std::string&)>& stage) {
  auto say = [&stage](const char* what) {
    if (stage) stage(what);
  };
  const auto start = std::chrono::steady_clock::now();
  PointResult out;
  out.point = p;
  out.key = key;
  const MeasureSetup m = measure_setup(p, setup.measure);
  out.ranges = register_ranges(p, setup.measure);
  SweepRow& row = out.row;
  row.width = m.first_stage.width;

  const std::string refusal = rtl_variant_refusal(p, setup.measure);
  const bool rtl = setup.rtl && refusal.empty();
  say("first stage, golden model, checker");
  const std::string tapes = setup.tape_dir + "/" + key;
  if (rtl) std::filesystem::create_directories(tapes);
  std::vector<std::string> tape_paths;
  for (size_t i = 0; i < setup.inputs.size(); ++i) {
    const std::string name = std::to_string(i) + "_" + std::filesystem::path(setup.inputs[i].path).stem().string();
    row.inputs.push_back(measure_input(setup.inputs[i], m.first_stage.width, m, rtl ? tapes + "/" + name + ".tape" : ""));
    if (!row.inputs.back().tape_path.empty()) tape_paths.push_back(row.inputs.back().tape_path);
  }

  if (setup.synthesis) {
    say("synthesis, place and route");
    try {
      row.synth = synthesize(rtl_parameters(p), setup.synth, setup.synth_key);
    } catch (const std::exception& e) {
      row.synth = synth_not_run(std::string("synthesis: ") + e.what());
    }
  } else {
    row.synth = synth_not_run("not run (--no-synth)");
  }

  if (rtl) {
    say("RTL variant: build and lock-step cosim");
    try {
      RtlVariantSetup variant = setup.rtl_variant;
      variant.clock_hz = m.clock_hz;
      row.rtl = run_rtl_variant(variant, RtlVariant{row.width, frac_digits_of(m.first_stage.blu_mm), m.arch, m.circle_mode},
                                tape_paths);
    } catch (const std::exception& e) {
      row.rtl.summary = std::string("RTL variant: ") + e.what();
    }
    std::error_code ec;
    std::filesystem::remove_all(tapes, ec);  // the tapes are remade from the inputs at any time
  } else {
    row.rtl.summary = setup.rtl ? refusal : "not run (--no-rtl)";
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace ncinterp::sweep
