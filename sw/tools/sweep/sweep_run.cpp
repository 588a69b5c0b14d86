// The grid's points on a thread pool (see sweep_run.h).
#include "sweep_run.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace ncinterp::sweep {

size_t run_missing_points(const Plan& plan, const std::string& dir, const PointSetup& setup, unsigned jobs,
                          const ProgressCallback& progress) {
  std::vector<const PlannedPoint*> todo;
  for (const PlannedPoint& p : plan.points)
    if (!load_result(dir, p.key)) todo.push_back(&p);
  const size_t total = todo.size();
  if (total == 0) return 0;
  std::atomic<size_t> next{0};
  std::mutex progress_mutex;
  size_t done = 0;
  auto report = [&](const std::string& point, const std::string& stage, bool finished) {
    if (!progress && !finished) return;
    std::lock_guard<std::mutex> lock(progress_mutex);
    if (finished) ++done;
    if (progress) progress({point, stage, done, total});
  };
  auto worker = [&]() {
    for (size_t i = next++; i < total; i = next++) {
      const PlannedPoint& p = *todo[i];
      const std::string text = point_text(p.point);
      store_result(dir, run_point(p.point, p.key, setup,
                                  [&](const std::string& stage) { report(text, stage, false); }));
      report(text, "done", true);
    }
  };
  jobs = jobs ? jobs : std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(std::min<size_t>(jobs, total));
  std::vector<std::thread> pool;
  for (unsigned j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();  // the calling thread is one of the workers
  for (std::thread& t : pool) t.join();
  return total;
}

bool run_one_point(const Plan& plan, const std::string& dir, const PointSetup& setup, const std::string& key) {
  const auto it = std::find_if(plan.points.begin(), plan.points.end(),
                               [&key](const PlannedPoint& p) { return p.key == key; });
  if (it == plan.points.end()) throw std::invalid_argument("--run-one: no point " + key + " in " + plan_path(dir));
  if (load_result(dir, key)) return false;
  store_result(dir, run_point(it->point, key, setup));
  return true;
}

}  // namespace ncinterp::sweep
