// The in-process runner of a grid (`ncinterp sweep ... --jobs N`): every planned point that
// has no result file yet is measured by run_point on a pool of threads and its result
// stored; points with a result are never run again.
// Idea: this is the same per-point code as `--run-one KEY` (which GNU parallel or a Slurm
// job array call once per point), only the scheduling differs; whatever fails at one point
// becomes that point's reason and the grid goes on.
#pragma once
#include <cstddef>
#include <functional>
#include <string>

#include "point_run.h"
#include "point_store.h"

namespace ncinterp::sweep {

struct SweepProgress {
  std::string point;          // the point's text
  std::string stage;          // what it is doing now ("done" when finished)
  size_t points_done = 0, points_total = 0;  // of the points that had to run
};
using ProgressCallback = std::function<void(const SweepProgress&)>;

// Runs the points of the plan without a result in dir; jobs 0: one per core. Returns the
// number of points run. progress (optional) is called from the workers, one call at a time.
size_t run_missing_points(const Plan& plan, const std::string& dir, const PointSetup& setup, unsigned jobs,
                          const ProgressCallback& progress = nullptr);

// Runs one planned point (by key) and stores its result, unless it has one already.
// Returns false when it had one. Throws std::invalid_argument for a key not in the plan.
bool run_one_point(const Plan& plan, const std::string& dir, const PointSetup& setup, const std::string& key);

}  // namespace ncinterp::sweep
