// Dense-sampling deviation meter (see deviation_meter.h).
#include "measure/deviation_meter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace ncinterp::firststage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One contour segment or one move, sampled at n + 1 evenly spaced points point(0..n), n
// steps of about the sampling step. Consecutive pieces of one run (no rapid between them)
// share their joint: the later one's point(0) is (up to rounding) the earlier one's point(n).
struct Piece {
  enum class Kind { kSegment, kLine, kArc } kind = Kind::kLine;
  long n = 1;
  bool first_of_run = true;  // its point(0) is a sample (otherwise the run's last one)
  bool straight = true;      // its samples lie on the segment point(0)-point(n)
  const Segment* segment = nullptr;          // kSegment
  Vec2 a, b;                                 // kLine: ends
  Vec2 c;                                    // kArc: centre; radius ra -> rb, angle ta + sweep
  double ra = 0, rb = 0, ta = 0, sweep = 0;  // kArc

  Vec2 point(long i) const {
    const double f = static_cast<double>(i) / n;
    switch (kind) {
      case Kind::kSegment: return segment->point(f);
      case Kind::kLine: return a + f * (b - a);
      case Kind::kArc: {
        const double r = ra + f * (rb - ra), th = ta + f * sweep;
        return c + r * Vec2{std::cos(th), std::sin(th)};
      }
    }
    return a;
  }
};

long steps_for(double length, double step) {
  return std::max(1L, static_cast<long>(std::ceil(length / step)));
}

Piece segment_piece(const Segment& s, double step) {
  // Length estimate from a coarse polyline, then an even parameter step.
  double len = 0.0;
  Vec2 prev = s.point(0.0);
  for (int i = 1; i <= 64; ++i) {
    const Vec2 p = s.point(i / 64.0);
    len += norm(p - prev);
    prev = p;
  }
  Piece pc;
  pc.kind = Piece::Kind::kSegment;
  pc.segment = &s;
  pc.n = steps_for(len, step);
  pc.straight = s.kind() == SegmentKind::kLine;  // point(u) is linear in u
  return pc;
}

Piece line_piece(Vec2 a, Vec2 b, double step) {
  Piece pc;
  pc.kind = Piece::Kind::kLine;
  pc.a = a;
  pc.b = b;
  pc.n = steps_for(norm(b - a), step);
  return pc;
}

Piece arc_piece(Vec2 a, Vec2 b, Vec2 c, bool ccw, double step) {
  Piece pc;
  pc.kind = Piece::Kind::kArc;
  pc.straight = false;
  pc.c = c;
  pc.ra = norm(a - c);
  pc.rb = norm(b - c);
  pc.ta = std::atan2(a.y - c.y, a.x - c.x);
  double sw = std::atan2(b.y - c.y, b.x - c.x) - pc.ta;
  if (ccw && sw <= 0) sw += 2 * M_PI;
  if (!ccw && sw >= 0) sw -= 2 * M_PI;
  pc.sweep = sw;
  pc.n = steps_for(std::fabs(sw) * std::max(pc.ra, pc.rb), step);
  return pc;
}

// The polyline through all samples of the pieces, as the target of distance queries.
// A curved piece keeps its n sample steps as segments, in chunks of kChunk consecutive
// ones; a straight piece is one segment (its samples are on it), cut into chunks about a
// cell long. A chunk's points are computed again when needed (no copy of the samples is
// kept). Chunks are found through a grid of square cells about a chunk long: the occupied
// cells, sorted, each with the chunks whose bounding box meets it.
class Target {
 public:
  static constexpr int kChunk = 128;

  Target(const std::vector<Piece>& pieces, double step)
      : pieces_(pieces), cell_(std::max(step * kChunk, 1e-6)) {
    for (uint32_t q = 0; q < pieces.size(); ++q) {
      const Piece& pc = pieces[q];
      const long m = pc.straight ? steps_for(norm(pc.point(pc.n) - pc.point(0)), cell_) : pc.n;
      segments_.push_back(m);
      for (long first = 0; first < m; first += pc.straight ? 1 : kChunk) {
        Chunk ch;
        ch.piece = q;
        ch.first = first;
        ch.count = pc.straight ? 1 : static_cast<uint32_t>(std::min<long>(kChunk, m - first));
        ch.lo = ch.hi = chunk_point(ch, 0);
        for (uint32_t i = 1; i <= ch.count; ++i) {
          const Vec2 p = chunk_point(ch, i);
          ch.lo = {std::min(ch.lo.x, p.x), std::min(ch.lo.y, p.y)};
          ch.hi = {std::max(ch.hi.x, p.x), std::max(ch.hi.y, p.y)};
        }
        chunks_.push_back(ch);
      }
    }
    std::vector<std::pair<uint64_t, uint32_t>> entries;
    for (uint32_t k = 0; k < chunks_.size(); ++k) {
      const Chunk& ch = chunks_[k];
      for (long x = cell_of(ch.lo.x); x <= cell_of(ch.hi.x); ++x)
        for (long y = cell_of(ch.lo.y); y <= cell_of(ch.hi.y); ++y)
          entries.push_back({key(x, y), k});
    }
    std::sort(entries.begin(), entries.end());
    for (size_t e = 0; e < entries.size(); ++e) {
      if (e == 0 || entries[e].first != entries[e - 1].first) {
        cell_keys_.push_back(entries[e].first);
        cell_starts_.push_back(static_cast<uint32_t>(e));
      }
      cell_chunks_.push_back(entries[e].second);
    }
    cell_starts_.push_back(static_cast<uint32_t>(entries.size()));
    seen_.assign(chunks_.size(), 0);
    cache_.resize(kCacheSlots);
  }

  bool empty() const { return chunks_.empty(); }

  // A segment of the polyline: chunk and segment within it.
  struct Where {
    uint32_t chunk = 0, i = 0;
  };

  double distance(Vec2 p, Where w) {
    const Vec2* pts = points(w.chunk);
    return distance_to_segment(p, pts[w.i], pts[w.i + 1]);
  }

  // Walks from w along the polyline while the distance to p decreases (at most a few
  // dozen segments): the distance to some segment near w, an upper bound of the true one.
  double walk(Vec2 p, Where& w) {
    double best = distance(p, w);
    for (int dir : {1, -1}) {
      bool moved = false;
      for (int n = 0; n < 32; ++n) {
        Where next = w;
        if (!step(next, dir)) break;
        const double d = distance(p, next);
        if (d >= best) break;
        best = d;
        w = next;
        moved = true;
      }
      if (moved) break;
    }
    return best;
  }

  // The exact distance from p to the polyline, given an upper bound (a distance to one of
  // its segments); w becomes the nearest segment.
  double nearest(Vec2 p, double bound, Where& w) {
    if (++stamp_ == 0) {  // wrapped around: forget every older stamp
      std::fill(seen_.begin(), seen_.end(), 0);
      stamp_ = 1;
    }
    double best = bound;
    const long cx = cell_of(p.x), cy = cell_of(p.y);
    // Cells of ring r (Chebyshev distance r from p's cell) are at least (r - 1) cells away.
    for (long r = 0; r <= kMaxRing; ++r) {
      if (best <= (r - 1) * cell_) return best;
      for (long x = cx - r; x <= cx + r; ++x) {
        const long dy = (x == cx - r || x == cx + r) ? 1 : 2 * r;  // full column or the two ends
        for (long y = cy - r; y <= cy + r; y += std::max(1L, dy)) visit_cell(p, key(x, y), best, w);
      }
    }
    // Farther than a few rings: every chunk, each pruned by its box.
    for (uint32_t k = 0; k < chunks_.size(); ++k) visit_chunk(p, k, best, w);
    return best;
  }

 private:
  struct Chunk {
    Vec2 lo, hi;          // bounding box of its points
    long first = 0;       // its first segment in the piece's target polyline
    uint32_t piece = 0;
    uint32_t count = 0;   // segments
  };
  static constexpr long kMaxRing = 4;  // farther than this, nearest() looks at every chunk
  static constexpr size_t kCacheSlots = 64;
  struct Slot {
    uint32_t chunk = UINT32_MAX;
    Vec2 pts[kChunk + 1];
  };

  Vec2 chunk_point(const Chunk& ch, uint32_t i) const {
    const Piece& pc = pieces_[ch.piece];
    if (!pc.straight) return pc.point(ch.first + i);
    const Vec2 a = pc.point(0), b = pc.point(pc.n);
    return a + (static_cast<double>(ch.first + i) / segments_[ch.piece]) * (b - a);
  }
  // A chunk's points, from a small direct-mapped cache (walks stay in one or two chunks).
  const Vec2* points(uint32_t k) {
    Slot& s = cache_[k % kCacheSlots];
    if (s.chunk != k) {
      s.chunk = k;
      for (uint32_t i = 0; i <= chunks_[k].count; ++i) s.pts[i] = chunk_point(chunks_[k], i);
    }
    return s.pts;
  }
  bool step(Where& w, int dir) const {
    if (dir > 0) {
      if (w.i + 1 < chunks_[w.chunk].count) return ++w.i, true;
      if (w.chunk + 1 >= chunks_.size()) return false;
      w = {w.chunk + 1, 0};
      return true;
    }
    if (w.i > 0) return --w.i, true;
    if (w.chunk == 0) return false;
    w = {w.chunk - 1, chunks_[w.chunk - 1].count - 1};
    return true;
  }
  void visit_cell(Vec2 p, uint64_t k, double& best, Where& w) {
    const auto it = std::lower_bound(cell_keys_.begin(), cell_keys_.end(), k);
    if (it == cell_keys_.end() || *it != k) return;
    const size_t c = it - cell_keys_.begin();
    for (uint32_t e = cell_starts_[c]; e < cell_starts_[c + 1]; ++e)
      visit_chunk(p, cell_chunks_[e], best, w);
  }
  void visit_chunk(Vec2 p, uint32_t k, double& best, Where& w) {
    if (seen_[k] == stamp_) return;
    seen_[k] = stamp_;
    const Chunk& ch = chunks_[k];
    const double dx = std::max({ch.lo.x - p.x, 0.0, p.x - ch.hi.x});
    const double dy = std::max({ch.lo.y - p.y, 0.0, p.y - ch.hi.y});
    if (std::sqrt(dx * dx + dy * dy) >= best) return;
    const Vec2* pts = points(k);
    for (uint32_t i = 0; i < ch.count; ++i) {
      const double d = distance_to_segment(p, pts[i], pts[i + 1]);
      if (d < best) best = d, w = {k, i};
    }
  }
  long cell_of(double v) const { return static_cast<long>(std::floor(v / cell_)); }
  static uint64_t key(long x, long y) {
    return (static_cast<uint64_t>(static_cast<uint32_t>(x)) << 32) | static_cast<uint32_t>(y);
  }

  const std::vector<Piece>& pieces_;
  double cell_;
  std::vector<long> segments_;          // per piece: its segments here (n, or cell-long cuts)
  std::vector<Chunk> chunks_;
  std::vector<uint64_t> cell_keys_;     // occupied cells, sorted
  std::vector<uint32_t> cell_starts_;   // cell c's chunks: cell_chunks_[starts[c] .. starts[c + 1])
  std::vector<uint32_t> cell_chunks_;
  std::vector<uint32_t> seen_;          // stamp of the last query that looked at a chunk
  uint32_t stamp_ = 0;
  std::vector<Slot> cache_;
};

// The largest distance from any sample of `from` to the polyline `to`. Samples are made one
// at a time. Each is first measured against the segments near the previous sample's nearest
// one (a walk); that distance is an upper bound, so when it does not exceed the running
// maximum the sample cannot raise it. Only the others are measured exactly.
double farthest(const std::vector<Piece>& from, Target& to, long* count) {
  double worst = 0.0;
  Target::Where w;
  for (const Piece& pc : from)
    for (long i = pc.first_of_run ? 0 : 1; i <= pc.n; ++i) {
      ++*count;
      if (to.empty()) {
        worst = kInf;
        continue;
      }
      const Vec2 p = pc.point(i);
      const double bound = to.walk(p, w);
      if (bound > worst) worst = std::max(worst, to.nearest(p, bound, w));
    }
  return worst;
}

}  // namespace

DeviationReport measure_deviation(const Contour& contour, GridPoint start,
                                  const std::vector<Move>& moves, double blu_mm, double step_mm) {
  std::vector<Piece> curve, path;
  bool run_open = false;  // a run continues across pieces until a rapid
  for (const Segment& s : contour.segments) {
    if (s.rapid) {
      run_open = false;
      continue;
    }
    curve.push_back(segment_piece(s, step_mm));
    curve.back().first_of_run = !run_open;
    run_open = true;
  }
  run_open = false;
  Vec2 cur = blu_mm * to_vec(start);
  for (const Move& m : moves) {
    const Vec2 to = blu_mm * to_vec(m.to);
    if (m.rapid) {
      run_open = false;
    } else {
      const bool ccw = m.kind == MoveKind::kArcCcw;
      path.push_back(m.kind == MoveKind::kLine
                         ? line_piece(cur, to, step_mm)
                         : arc_piece(cur, to, blu_mm * to_vec(m.centre), ccw, step_mm));
      path.back().first_of_run = !run_open;
      run_open = true;
    }
    cur = to;
  }
  DeviationReport r;
  Target curve_target(curve, step_mm), path_target(path, step_mm);
  r.path_to_contour_mm = farthest(path, curve_target, &r.samples);
  r.contour_to_path_mm = farthest(curve, path_target, &r.samples);
  r.max_mm = std::max(r.path_to_contour_mm, r.contour_to_path_mm);
  return r;
}

}  // namespace ncinterp::firststage
