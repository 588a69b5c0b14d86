// Plan and result files (see point_store.h).
#include "point_store.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "atomic_file.h"
#include "synth_cache.h"

namespace ncinterp::sweep {
namespace {

using nlohmann::json;

json point_json(const DesignPoint& p) {
  json j = json::object();
  for (const auto& [name, value] : p) j[name] = value;
  return j;
}

DesignPoint point_from_json(const json& j) {
  DesignPoint p;
  for (const auto& [name, value] : j.items()) p[name] = value.get<double>();
  return p;
}

json input_json(const InputResult& in) {
  return {{"input", in.input},
          {"failure", in.failure},
          {"blocks", in.blocks},
          {"frames", in.frames},
          {"path_error_max_blu", in.path_error_max_blu},
          {"total_error_max_mm", in.total_error_max_mm},
          {"violations", in.violations},
          {"first_violation", in.first_violation},
          {"feed_error_worst", in.feed_error_worst},
          {"saturated_blocks", in.saturated_blocks},
          {"cycles", in.cycles}};
}

InputResult input_from_json(const json& j) {
  InputResult in;
  in.input = j.at("input").get<std::string>();
  in.failure = j.at("failure").get<std::string>();
  in.blocks = j.at("blocks").get<uint64_t>();
  in.frames = j.at("frames").get<uint64_t>();
  in.path_error_max_blu = j.at("path_error_max_blu").get<double>();
  in.total_error_max_mm = j.at("total_error_max_mm").get<double>();
  in.violations = j.at("violations").get<uint64_t>();
  in.first_violation = j.at("first_violation").get<std::string>();
  in.feed_error_worst = j.at("feed_error_worst").get<double>();
  in.saturated_blocks = j.at("saturated_blocks").get<uint64_t>();
  in.cycles = j.at("cycles").get<uint64_t>();
  return in;
}

}  // namespace

std::string plan_path(const std::string& dir) { return dir + "/plan.json"; }
std::string result_path(const std::string& dir, const std::string& key) { return dir + "/points/" + key + ".json"; }

void write_plan(const std::string& dir, const Plan& plan) {
  json points = json::array();
  for (const PlannedPoint& p : plan.points) points.push_back({{"key", p.key}, {"point", point_json(p.point)}});
  const json j = {{"settings", plan.settings}, {"inputs", plan.inputs}, {"axes", plan.axes}, {"points", points}};
  std::filesystem::create_directories(dir);
  write_file_atomically(plan_path(dir), j.dump(1) + "\n");
}

Plan read_plan(const std::string& dir) {
  const std::string path = plan_path(dir);
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": no plan (write one with ncinterp sweep ... --plan --cache " + dir + ")");
  try {
    const json j = json::parse(in);
    Plan plan;
    plan.settings = j.at("settings");
    plan.inputs = j.at("inputs").get<std::vector<std::string>>();
    plan.axes = j.at("axes").get<std::vector<std::string>>();
    for (const json& p : j.at("points"))
      plan.points.push_back({point_from_json(p.at("point")), p.at("key").get<std::string>()});
    return plan;
  } catch (const json::exception& e) {
    throw std::runtime_error(path + ": malformed plan: " + e.what());
  }
}

json point_result_json(const PointResult& r) {
  json inputs = json::array();
  for (const InputResult& in : r.row.inputs) inputs.push_back(input_json(in));
  return {{"key", r.key},
          {"point", point_json(r.point)},
          {"seconds", r.seconds},
          {"width", r.row.width},
          {"inputs", inputs},
          {"synth", synth_result_json(r.row.synth)},
          {"rtl", {{"ran", r.row.rtl.ran}, {"all_match", r.row.rtl.all_match}, {"summary", r.row.rtl.summary}}},
          {"ranges",
           {{"max_move_mm", r.ranges.max_move_mm},
            {"pos_range_mm", r.ranges.pos_range_mm},
            {"feed_min_mm_min", r.ranges.feed_min_mm_min},
            {"feed_max_mm_min", r.ranges.feed_max_mm_min},
            {"feed_max_clock_mm_min", r.ranges.feed_max_clock_mm_min}}}};
}

PointResult point_result_from_json(const json& j) {
  PointResult r;
  r.key = j.at("key").get<std::string>();
  r.point = point_from_json(j.at("point"));
  r.seconds = j.at("seconds").get<double>();
  r.row.width = j.at("width").get<unsigned>();
  for (const json& in : j.at("inputs")) r.row.inputs.push_back(input_from_json(in));
  r.row.synth = synth_result_from_json(j.at("synth"));
  const json& rtl = j.at("rtl");
  r.row.rtl.ran = rtl.at("ran").get<bool>();
  r.row.rtl.all_match = rtl.at("all_match").get<bool>();
  r.row.rtl.summary = rtl.at("summary").get<std::string>();
  const json& g = j.at("ranges");
  r.ranges.max_move_mm = g.at("max_move_mm").get<double>();
  r.ranges.pos_range_mm = g.at("pos_range_mm").get<double>();
  r.ranges.feed_min_mm_min = g.at("feed_min_mm_min").get<double>();
  r.ranges.feed_max_mm_min = g.at("feed_max_mm_min").get<double>();
  r.ranges.feed_max_clock_mm_min = g.at("feed_max_clock_mm_min").get<double>();
  return r;
}

void store_result(const std::string& dir, const PointResult& r) {
  std::filesystem::create_directories(dir + "/points");
  write_file_atomically(result_path(dir, r.key), point_result_json(r).dump(1) + "\n");
}

std::optional<PointResult> load_result(const std::string& dir, const std::string& key) {
  std::ifstream in(result_path(dir, key));
  if (!in) return std::nullopt;
  try {
    PointResult r = point_result_from_json(json::parse(in));
    if (r.key != key) return std::nullopt;
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::vector<PointResult> collect_results(const std::string& dir, const Plan& plan) {
  std::vector<PointResult> out;
  for (const PlannedPoint& p : plan.points) {
    if (std::optional<PointResult> r = load_result(dir, p.key)) {
      out.push_back(std::move(*r));
      continue;
    }
    PointResult missing;
    missing.point = p.point;
    missing.key = p.key;
    missing.row.width = static_cast<unsigned>(point_value(p.point, kIncWidth, 0));
    const std::string why = "not run: no result file " + p.key + ".json";
    for (const std::string& name : plan.inputs) {
      InputResult in;
      in.input = name;
      in.failure = why;
      missing.row.inputs.push_back(in);
    }
    missing.row.synth.cells = missing.row.synth.flip_flops = missing.row.synth.ice40_luts =
        missing.row.synth.ice40_logic_cells = missing.row.synth.fmax_mhz = missing.row.synth.small_logic_cells =
            missing.row.synth.small_fmax_mhz = Measured::absent(why);
    missing.row.rtl.summary = why;
    out.push_back(std::move(missing));
  }
  return out;
}

}  // namespace ncinterp::sweep
