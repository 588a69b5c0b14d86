// Pareto front and board recommendations (see pareto.h).
#include "pareto.h"

#include <cmath>
#include <cstdio>
#include <utility>

namespace ncinterp::sweep {
namespace {

// Total errors closer than this are a tie for the recommendation: a tenth of a micrometre,
// below what a tape of the finest BLU (0.001 mm) can express.
constexpr double kErrorTieMm = 1e-4;

bool passed(const PointResult& r) {
  if (!r.row.missing_input().empty()) return false;
  for (const InputResult& in : r.row.inputs)
    if (in.violations) return false;
  return true;
}

std::optional<double> objective(const PointResult& r, const std::string& name) {
  if (name == "ice40_logic_cells") return r.row.synth.ice40_logic_cells.value;
  if (name == "total_error_max_mm") return r.row.worst(&InputResult::total_error_max_mm);
  const std::optional<uint64_t> frames = r.row.total(&InputResult::frames);
  return frames ? std::optional<double>(static_cast<double>(*frames)) : std::nullopt;
}

// a dominates b: no worse on every objective, better on one.
bool dominates(const std::vector<double>& a, const std::vector<double>& b) {
  bool better = false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i] > b[i]) return false;
    if (a[i] < b[i]) better = true;
  }
  return better;
}

// The board holds the point's logic and runs at its clock: the placement judged (the
// HX1K's own, else the HX8K's) has the cells and an Fmax of at least the point's clock.
bool fits(const PointResult& r, const Board& b, double default_clock_hz) {
  const SynthResult& s = r.row.synth;
  const Measured& cells = b.small_part ? s.small_logic_cells : s.ice40_logic_cells;
  const Measured& fmax = b.small_part ? s.small_fmax_mhz : s.fmax_mhz;
  const double clock_mhz = point_value(r.point, kClock, default_clock_hz) / 1e6;
  return cells.ok() && fmax.ok() && *cells.value <= b.logic_cells && *fmax.value >= clock_mhz;
}

}  // namespace

ParetoFront pareto_front(const std::vector<PointResult>& results) {
  ParetoFront f;
  bool any_area = false;
  for (const PointResult& r : results) any_area |= passed(r) && r.row.synth.ice40_logic_cells.ok();
  if (any_area) f.objectives.push_back("ice40_logic_cells");
  f.objectives.push_back("total_error_max_mm");
  f.objectives.push_back("tape_frames");

  std::vector<size_t> eligible;
  std::vector<std::vector<double>> values(results.size());
  for (size_t i = 0; i < results.size(); ++i) {
    if (!passed(results[i])) continue;
    bool all = true;
    for (const std::string& o : f.objectives) {
      const std::optional<double> v = objective(results[i], o);
      if (!v) all = false;
      else values[i].push_back(*v);
    }
    if (all) eligible.push_back(i);
  }
  f.eligible = eligible.size();
  for (size_t i : eligible) {
    bool beaten = false;
    for (size_t j : eligible) beaten |= j != i && dominates(values[j], values[i]);
    if (!beaten) f.members.push_back(i);
  }
  return f;
}

const std::vector<Board>& target_boards() {
  static const std::vector<Board> boards = {{"HX1K", 1280, true}, {"UP5K", 5280, false}, {"HX8K", 7680, false}};
  return boards;
}

std::vector<Recommendation> recommend(const std::vector<PointResult>& results, const ParetoFront& front,
                                      double default_clock_hz) {
  std::vector<Recommendation> out;
  const bool has_area = !front.objectives.empty() && front.objectives.front() == "ice40_logic_cells";
  for (const Board& b : target_boards()) {
    Recommendation rec{b, std::nullopt, ""};
    if (!has_area) {
      rec.why = "no area measured (synthesis not run)";
      out.push_back(rec);
      continue;
    }
    auto better = [&](size_t i, size_t j) {  // i before j by the rule
      const std::pair<const char*, double> rule[] = {  // objective, what counts as a tie
          {"total_error_max_mm", kErrorTieMm}, {"tape_frames", 0.0}, {"ice40_logic_cells", 0.0}};
      for (const auto& [o, tie] : rule) {
        const double a = *objective(results[i], o), c = *objective(results[j], o);
        if (std::abs(a - c) > tie) return a < c;
      }
      // Then what the clock buys: the block times closest to 1/F.
      const double fi = std::abs(results[i].row.worst(&InputResult::feed_error_worst).value_or(1e300));
      const double fj = std::abs(results[j].row.worst(&InputResult::feed_error_worst).value_or(1e300));
      if (fi != fj) return fi < fj;
      return i < j;
    };
    for (size_t i : front.members)
      if (fits(results[i], b, default_clock_hz) && (!rec.point || better(i, *rec.point))) rec.point = i;
    if (rec.point) {
      rec.why = "first by the rule (total error, tape, area, feed error) of the front's points that fit";
    } else {
      char buf[128];
      std::snprintf(buf, sizeof buf, "no point of the front fits (%.0f logic cells, Fmax at least its clock)",
                    b.logic_cells);
      rec.why = buf;
    }
    out.push_back(rec);
  }
  return out;
}

}  // namespace ncinterp::sweep
