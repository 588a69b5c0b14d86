// Result files of design points and the plan of a grid, in one cache directory:
//   <dir>/plan.json          the settings and every point with its key (ncinterp sweep --plan)
//   <dir>/points/<key>.json  one point's result (--run-one KEY, or --jobs N in process)
// Idea: a result file is content-addressed (point_run.h: the key hashes everything the
// result depends on), written atomically and only when the point ran to its end, so
// runners need no coordination: any machine may run any point in any order, a point that
// has a file is never run again, and collecting reads the files in the plan's order.
// The result file holds no time stamp or host; only the wall time of the run, which the
// tables leave out (it goes to the separate timing table).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "point_run.h"

namespace ncinterp::sweep {

struct PlannedPoint {
  DesignPoint point;
  std::string key;
};

struct Plan {
  nlohmann::json settings;          // the command's options, enough to rebuild the setup
  std::vector<std::string> inputs;  // the input files, in the command's order
  std::vector<std::string> axes;    // parameter names in grid order (the tables' columns)
  std::vector<PlannedPoint> points; // in grid order
};

std::string plan_path(const std::string& dir);
std::string result_path(const std::string& dir, const std::string& key);

void write_plan(const std::string& dir, const Plan& plan);  // atomically
// Throws std::runtime_error naming the file when there is no plan or it is malformed.
Plan read_plan(const std::string& dir);

nlohmann::json point_result_json(const PointResult& r);
PointResult point_result_from_json(const nlohmann::json& j);  // throws on a malformed object

void store_result(const std::string& dir, const PointResult& r);  // atomically
// The stored result of the key, or nullopt when there is none (or it cannot be read: it is
// then run again).
std::optional<PointResult> load_result(const std::string& dir, const std::string& key);

// The results of every planned point in the plan's order; a point without a result file
// gets a row whose every input says so ("not run: no result file <key>.json").
std::vector<PointResult> collect_results(const std::string& dir, const Plan& plan);

}  // namespace ncinterp::sweep
