// Cutter-centre offset of chord chains (see cutter_offset.h): the edge, on the cutter's side,
// of the region nearer than R to the chain, computed as the boundary of a union of discs.
#include "offset/cutter_offset.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace ncinterp::firststage {
namespace {

// BLU. kClear: what a distance may miss R by and still count as R (the rounding of the
// geometry is below 1e-9 BLU up to 10^6 BLU). kMerge: points nearer than this are one; it
// folds up the crossings of nearly parallel offsets and stays far inside the 1 BLU of delta
// kept for rounding the path to the grid.
constexpr double kClear = 1e-8;
constexpr double kMerge = 0.05;

// A uniform grid of boxes, cell size at least R: which items may come within R of a point or
// meet each other.
class Grid {
 public:
  explicit Grid(double cell) : cell_(cell) {}
  void add(int item, Vec2 lo, Vec2 hi) {
    for (int64_t i = key(lo.x); i <= key(hi.x); ++i)
      for (int64_t j = key(lo.y); j <= key(hi.y); ++j) cells_[pack(i, j)].push_back(item);
  }
  const std::unordered_map<int64_t, std::vector<int>>& cells() const { return cells_; }
  int64_t cell_of(Vec2 p) const { return pack(key(p.x), key(p.y)); }
  // Calls f for the items in the cells around p (all that can be within one cell of p).
  template <class F>
  void around(Vec2 p, F f) const {
    const int64_t i0 = key(p.x), j0 = key(p.y);
    for (int64_t i = i0 - 1; i <= i0 + 1; ++i)
      for (int64_t j = j0 - 1; j <= j0 + 1; ++j) {
        const auto it = cells_.find(pack(i, j));
        if (it != cells_.end())
          for (const int item : it->second) f(item);
      }
  }

 private:
  int64_t key(double v) const { return static_cast<int64_t>(std::floor(v / cell_)); }
  static int64_t pack(int64_t i, int64_t j) { return i * 4294967311LL + j; }
  double cell_;
  std::unordered_map<int64_t, std::vector<int>> cells_;
};

// The path around centre c from angle a0 by the signed angle `sweep` at radius r: a polygon
// circumscribed about the circle, each piece turning by at most 90 degrees, every vertex the
// intersection of two tangents: the cutter touches the chord vertex all the way round and is
// never nearer to it than R. Up to 90 degrees that is the one intersection of the two
// tangents (at a whole convex corner, of the two chords' offset lines).
void around(Vec2 c, double a0, double sweep, double r, std::vector<Vec2>& out) {
  if (std::fabs(sweep) <= 1e-12) return;
  const int pieces = static_cast<int>(std::ceil(std::fabs(sweep) / (M_PI / 2) - 1e-12));
  const double phi = sweep / pieces;
  const double reach = r / std::cos(0.5 * phi);
  for (int j = 0; j < pieces; ++j) {
    const double ang = a0 + (j + 0.5) * phi;
    out.push_back(c + reach * Vec2{std::cos(ang), std::sin(ang)});
  }
}

bool straight_on(Vec2 d0, Vec2 d1) {
  return std::fabs(cross(d0, d1)) <= 1e-9 * norm(d0) * norm(d1) && dot(d0, d1) > 0;
}

// The offset of one chain of chord vertices (see offset_chain below).
class ChainOffset {
 public:
  ChainOffset(const std::vector<Vec2>& pts, const std::vector<int>& elements, double r, bool left);
  // The path's vertices and, per vertex after the first, the element of the move ending there.
  void run(std::vector<Vec2>* out, std::vector<int>* out_elements);

 private:
  struct Chord {
    Vec2 p, q, n;  // ends, unit normal toward the cutter
    int element;
    int from, to;     // vertices
  };
  // A piece of the edge of the union: a chord's offset on the cutter's side (front) or on
  // the other (back), or the circle about a vertex. Each is followed with the chain on the
  // same hand: a front along its chord, a back against it, a circle clockwise with the
  // cutter on the left.
  struct Edge {
    enum Kind { kFront, kBack, kCircle } kind = kFront;
    Vec2 a, b;         // front, back: ends in the order followed
    Vec2 c;            // circle: centre
    int own = -1;      // front, back: the chord; circle: the vertex
    int element = -1;  // input element a move along it belongs to
    // Cuts: parameter (front, back: 0..1 from a to b; circle: angle in the sense followed,
    // 0..2 pi) and node.
    std::vector<std::pair<double, int>> stops;
  };
  // The part of an edge between two consecutive stops.
  struct Stretch {
    int edge;
    double t0, t1;  // a circle's t1 may pass 2 pi
    int from, to;   // nodes
  };

  void make_edges();
  void cut();
  void make_stretches();
  std::vector<std::vector<int>> curves() const;
  std::vector<int> path_of(const std::vector<std::vector<int>>& curves) const;

  int new_node(Vec2 x) {
    node_at_.push_back(x);
    parent_.push_back(static_cast<int>(parent_.size()));
    return static_cast<int>(parent_.size()) - 1;
  }
  int find(int k) {
    while (parent_[k] != k) k = parent_[k] = parent_[parent_[k]];
    return k;
  }
  double circle_param(Vec2 c, Vec2 x) const {
    const double a = sense_ * std::atan2(x.y - c.y, x.x - c.x);
    return a < 0 ? a + 2 * M_PI : a;
  }
  Vec2 point_on(const Edge& e, double t) const {
    if (e.kind != Edge::kCircle) return e.a + t * (e.b - e.a);
    return e.c + r_ * Vec2{std::cos(sense_ * t), std::sin(sense_ * t)};
  }
  Vec2 direction(const Stretch& s, bool at_end) const {
    const Edge& e = edges_[s.edge];
    if (e.kind != Edge::kCircle) return unit(e.b - e.a);
    const double t = sense_ * (at_end ? s.t1 : s.t0);
    return sense_ * Vec2{-std::sin(t), std::cos(t)};
  }
  // No nearer than R to any chord (up to kClear).
  bool clear(Vec2 x) const {
    bool ok = true;
    near_.around(x, [&](int k) { ok = ok && distance_to_segment(x, chords_[k].p, chords_[k].q) >= r_ - kClear; });
    return ok;
  }
  // Nearer than R to a chord beside edge e (the chords before and after its chord or vertex).
  bool inside_beside(const Edge& e, Vec2 x) const;
  double front_length(const std::vector<int>& curve) const;
  bool is_end_circle(int stretch) const {
    const Edge& e = edges_[stretches_[stretch].edge];
    return !closed_ && e.kind == Edge::kCircle && (e.own == 0 || e.own == static_cast<int>(vertices_.size()) - 1);
  }

  double r_;
  bool closed_;
  double sense_;  // +1: circles counter-clockwise (cutter on the right)
  std::vector<Chord> chords_;
  std::vector<Vec2> vertices_;
  std::vector<std::array<int, 2>> vertex_chords_;  // chords before and after (-1: none)
  double cell_ = 1.0;                              // grid cell size
  Grid near_;                                      // chords
  std::vector<Edge> edges_;
  std::vector<Vec2> node_at_;
  std::vector<int> parent_;  // node merging
  std::vector<Stretch> stretches_;  // those on the edge of the union only
  std::vector<std::vector<int>> leaving_;  // per node, the stretches starting there
};

ChainOffset::ChainOffset(const std::vector<Vec2>& pts, const std::vector<int>& elements, double r, bool left)
    : r_(r), closed_(pts.size() > 3 && norm(pts.front() - pts.back()) == 0.0), sense_(left ? -1.0 : 1.0), near_(1.0) {
  for (size_t k = 0; k + 1 < pts.size(); ++k) {
    const Vec2 d = unit(pts[k + 1] - pts[k]);
    if (norm(d) == 0.0) continue;
    if (vertices_.empty()) vertices_.push_back(pts[k]);
    const int from = static_cast<int>(vertices_.size()) - 1;
    vertices_.push_back(pts[k + 1]);
    chords_.push_back({pts[k], pts[k + 1], left ? perp(d) : -1.0 * perp(d), elements[k], from, from + 1});
  }
  if (closed_ && !chords_.empty()) {  // the last vertex is the first
    vertices_.pop_back();
    chords_.back().to = 0;
  }
  vertex_chords_.assign(vertices_.size(), {-1, -1});
  double longest = 0;
  for (size_t k = 0; k < chords_.size(); ++k) {
    vertex_chords_[chords_[k].to][0] = static_cast<int>(k);
    vertex_chords_[chords_[k].from][1] = static_cast<int>(k);
    longest = std::max(longest, norm(chords_[k].q - chords_[k].p));
  }
  // Cells of at least R (so the cells around a point hold every chord within R of it), and
  // not so small that a long chord fills thousands.
  cell_ = std::max({r_, 1.0, longest / 64});
  near_ = Grid(cell_);
  for (size_t k = 0; k < chords_.size(); ++k) {
    const Chord& c = chords_[k];
    near_.add(static_cast<int>(k), {std::min(c.p.x, c.q.x), std::min(c.p.y, c.q.y)},
              {std::max(c.p.x, c.q.x), std::max(c.p.y, c.q.y)});
  }
}

// Per vertex its circle, per chord its front and back. A front or back ends on the circles
// about its chord's ends, where it touches them: those points are nodes from the start.
void ChainOffset::make_edges() {
  for (size_t v = 0; v < vertices_.size(); ++v) {
    Edge e;
    e.kind = Edge::kCircle;
    e.c = vertices_[v];
    e.own = static_cast<int>(v);
    const auto [before, after] = vertex_chords_[v];
    e.element = chords_[before >= 0 ? before : after].element;  // the chord before, if any
    edges_.push_back(e);
  }
  for (size_t k = 0; k < chords_.size(); ++k) {
    const Chord& ch = chords_[k];
    for (const Edge::Kind kind : {Edge::kFront, Edge::kBack}) {
      const bool front = kind == Edge::kFront;
      Edge e;
      e.kind = kind;
      e.a = (front ? ch.p : ch.q) + (front ? r_ : -r_) * ch.n;
      e.b = (front ? ch.q : ch.p) + (front ? r_ : -r_) * ch.n;
      e.own = static_cast<int>(k);
      e.element = ch.element;
      const int na = new_node(e.a), nb = new_node(e.b);
      e.stops = {{0.0, na}, {1.0, nb}};
      Edge& ca = edges_[front ? ch.from : ch.to];
      Edge& cb = edges_[front ? ch.to : ch.from];
      ca.stops.push_back({circle_param(ca.c, e.a), na});
      cb.stops.push_back({circle_param(cb.c, e.b), nb});
      edges_.push_back(e);
    }
  }
}

bool ChainOffset::inside_beside(const Edge& e, Vec2 x) const {
  const int m = static_cast<int>(chords_.size());
  const auto near_chord = [&](int k) {
    if (closed_) k = (k + m) % m;
    return k >= 0 && k < m && distance_to_segment(x, chords_[k].p, chords_[k].q) < r_ - kClear;
  };
  if (e.kind == Edge::kCircle) return near_chord(vertex_chords_[e.own][0]) || near_chord(vertex_chords_[e.own][1]);
  return near_chord(e.own - 1) || near_chord(e.own + 1);
}

// Cuts the edges where they cross. A front or back only touches the circles about its own
// chord's ends (at its ends), and a chord's front and back are parallel. A crossing strictly
// inside the union is on no stretch of the edge and cuts nothing that matters; most crossings
// of neighbouring circles are such, and are left out.
void ChainOffset::cut() {
  const int ne = static_cast<int>(edges_.size());
  Grid grid(cell_);
  std::vector<std::pair<Vec2, Vec2>> box(ne);
  for (int k = 0; k < ne; ++k) {
    const Edge& e = edges_[k];
    box[k] = e.kind == Edge::kCircle ? std::make_pair(e.c - Vec2{r_, r_}, e.c + Vec2{r_, r_})
                                     : std::make_pair(Vec2{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y)},
                                                      Vec2{std::max(e.a.x, e.b.x), std::max(e.a.y, e.b.y)});
    grid.add(k, box[k].first, box[k].second);
  }
  const auto in01 = [](double t) { return t >= -1e-12 && t <= 1 + 1e-12; };
  const auto cross_at = [&](int i, int j, Vec2 x, double ti, double tj) {
    const int node = new_node(x);
    edges_[i].stops.push_back({ti, node});
    edges_[j].stops.push_back({tj, node});
  };
  for (const auto& [cell, items] : grid.cells())
    for (size_t x = 0; x < items.size(); ++x)
      for (size_t y = x + 1; y < items.size(); ++y) {
        int i = items[x], j = items[y];
        // Each pair once: in the cell holding the low corner of their boxes' overlap.
        const Vec2 lo{std::max(box[i].first.x, box[j].first.x), std::max(box[i].first.y, box[j].first.y)};
        if (lo.x > std::min(box[i].second.x, box[j].second.x) || lo.y > std::min(box[i].second.y, box[j].second.y) ||
            grid.cell_of(lo) != cell)
          continue;
        if (edges_[i].kind != Edge::kCircle && edges_[j].kind == Edge::kCircle) std::swap(i, j);
        const Edge &p = edges_[i], &q = edges_[j];
        const auto keep = [&](Vec2 pt) { return !inside_beside(p, pt) && !inside_beside(q, pt); };
        if (p.kind == Edge::kCircle && q.kind == Edge::kCircle) {
          const Vec2 cc = q.c - p.c;
          const double dist = norm(cc);
          if (dist == 0.0 || dist >= 2 * r_) continue;
          const Vec2 mid = p.c + 0.5 * cc, h = std::sqrt(r_ * r_ - 0.25 * dist * dist) * perp(unit(cc));
          for (const Vec2 pt : {mid + h, mid - h})
            if (keep(pt)) cross_at(i, j, pt, circle_param(p.c, pt), circle_param(q.c, pt));
        } else if (p.kind == Edge::kCircle) {  // and a segment
          if (p.own == chords_[q.own].from || p.own == chords_[q.own].to) continue;
          const Vec2 d = q.b - q.a, w = q.a - p.c;
          const double A = dot(d, d), B = 2 * dot(d, w), C = dot(w, w) - r_ * r_, disc = B * B - 4 * A * C;
          if (disc <= 0) continue;  // a touch is no crossing
          for (const double sgn : {-1.0, 1.0}) {
            const double t = (-B + sgn * std::sqrt(disc)) / (2 * A);
            if (!in01(t)) continue;
            const Vec2 pt = q.a + std::clamp(t, 0.0, 1.0) * d;
            if (keep(pt)) cross_at(i, j, pt, circle_param(p.c, pt), std::clamp(t, 0.0, 1.0));
          }
        } else {  // two segments
          if (p.own == q.own) continue;
          const Vec2 d1 = p.b - p.a, d2 = q.b - q.a;
          const double den = cross(d1, d2);
          if (std::fabs(den) <= 1e-12 * norm(d1) * norm(d2)) continue;
          const double t = cross(q.a - p.a, d2) / den, u = cross(q.a - p.a, d1) / den;
          if (!in01(t) || !in01(u)) continue;
          const Vec2 pt = p.a + std::clamp(t, 0.0, 1.0) * d1;
          if (keep(pt)) cross_at(i, j, pt, std::clamp(t, 0.0, 1.0), std::clamp(u, 0.0, 1.0));
        }
      }
}

// Each edge's stretches run between consecutive stops (a circle's also from the last round to
// the first); stops nearer than kMerge are one node. A stretch is on the edge of the union if
// it is nowhere nearer than R to a chord: between cuts it is wholly in or out, so its middle
// decides.
void ChainOffset::make_stretches() {
  for (Edge& e : edges_) {
    std::sort(e.stops.begin(), e.stops.end());
    std::vector<std::pair<double, int>> merged;
    for (const auto& s : e.stops) {
      if (!merged.empty() && norm(node_at_[s.second] - node_at_[merged.back().second]) <= kMerge) {
        parent_[find(s.second)] = find(merged.back().second);
        continue;
      }
      merged.push_back(s);
    }
    if (e.kind == Edge::kCircle && merged.size() > 1 &&
        norm(node_at_[merged.back().second] - node_at_[merged.front().second]) <= kMerge) {
      parent_[find(merged.back().second)] = find(merged.front().second);
      merged.pop_back();
    }
    e.stops = std::move(merged);
  }
  leaving_.assign(node_at_.size(), {});
  for (size_t k = 0; k < edges_.size(); ++k) {
    const Edge& e = edges_[k];
    const size_t m = e.stops.size();
    const size_t count = e.kind == Edge::kCircle ? m : m - 1;
    for (size_t j = 0; j < count; ++j) {
      const auto& s0 = e.stops[j];
      const double t1 = j + 1 == m ? e.stops[0].first + 2 * M_PI : e.stops[j + 1].first;
      const int from = find(s0.second), to = find(e.stops[(j + 1) % m].second);
      if (from == to || !clear(point_on(e, 0.5 * (s0.first + t1)))) continue;
      leaving_[from].push_back(static_cast<int>(stretches_.size()));
      stretches_.push_back({static_cast<int>(k), s0.first, t1, from, to});
    }
  }
}

// The kept stretches joined end to end into closed curves. Where more than one stretch leaves
// a node (curves touching there), the one turning most toward the chain keeps the union on the
// same hand.
std::vector<std::vector<int>> ChainOffset::curves() const {
  std::vector<std::vector<int>> out;
  std::vector<bool> used(stretches_.size(), false);
  for (size_t s0 = 0; s0 < stretches_.size(); ++s0) {
    if (used[s0]) continue;
    std::vector<int> curve{static_cast<int>(s0)};
    used[s0] = true;
    for (int s = static_cast<int>(s0);;) {
      const int at = stretches_[s].to;
      if (at == stretches_[s0].from) {
        out.push_back(std::move(curve));
        break;
      }
      int next = -1;
      double best_turn = 0;
      const Vec2 in = direction(stretches_[s], true);
      for (const int t : leaving_[at]) {
        if (used[t]) continue;
        const Vec2 o = direction(stretches_[t], false);
        const double turn = sense_ * std::atan2(cross(in, o), dot(in, o));
        if (next < 0 || turn > best_turn) {
          next = t;
          best_turn = turn;
        }
      }
      if (next < 0) break;  // does not close (only from rounding): not a curve of the edge
      used[next] = true;
      curve.push_back(next);
      s = next;
    }
  }
  return out;
}

double ChainOffset::front_length(const std::vector<int>& curve) const {
  double len = 0;
  for (const int s : curve) {
    const Edge& e = edges_[stretches_[s].edge];
    if (e.kind == Edge::kFront) len += norm(e.b - e.a) * (stretches_[s].t1 - stretches_[s].t0);
  }
  return len;
}

// The cutter's curve is the one with the most front on it. The others lie on the other side
// of the chain, or inside the part beyond a wall thinner than 2R, or in a part of a pocket
// the cutter cannot pass into (that part stays uncut). A closed chain's path is that curve,
// from the first chord's front. An open chain's runs on the cutter's side from one end to the
// other while the curve goes round the chain: the path is the run between two backs that
// holds the fronts, without the circles about the chain's end points (it starts and ends on
// them: on the normal offset of the end point, or where a neighbouring chord's offset meets
// the circle first, so the cutter never backs up into the chord before it).
std::vector<int> ChainOffset::path_of(const std::vector<std::vector<int>>& curves) const {
  const std::vector<int>* best = nullptr;
  double best_length = 0;
  for (const auto& c : curves) {
    const double length = front_length(c);
    if (length > best_length) best = &c, best_length = length;
  }
  if (!best) return {};
  std::vector<int> curve = *best;
  const auto kind_of = [&](int s) { return edges_[stretches_[s].edge].kind; };
  if (closed_) {
    size_t first = 0;
    for (size_t i = 0; i < curve.size(); ++i)
      if (kind_of(curve[i]) == Edge::kFront && (kind_of(curve[first]) != Edge::kFront ||
                                                 edges_[stretches_[curve[i]].edge].own < edges_[stretches_[curve[first]].edge].own))
        first = i;
    std::rotate(curve.begin(), curve.begin() + static_cast<long>(first), curve.end());
    return curve;
  }
  const auto back = std::find_if(curve.begin(), curve.end(), [&](int s) { return kind_of(s) == Edge::kBack; });
  std::rotate(curve.begin(), back == curve.end() ? curve.begin() : back, curve.end());
  std::vector<int> run, best_run;
  double best_run_length = 0;
  for (const int s : curve) {
    if (kind_of(s) != Edge::kBack) run.push_back(s);
    if (kind_of(s) == Edge::kBack || s == curve.back()) {
      const double length = front_length(run);
      if (length > best_run_length) best_run = run, best_run_length = length;
      run.clear();
    }
  }
  while (!best_run.empty() && is_end_circle(best_run.front())) best_run.erase(best_run.begin());
  while (!best_run.empty() && is_end_circle(best_run.back())) best_run.pop_back();
  return best_run;
}

void ChainOffset::run(std::vector<Vec2>* out, std::vector<int>* out_elements) {
  if (chords_.empty()) return;
  make_edges();
  cut();
  make_stretches();
  const std::vector<int> path = path_of(curves());
  if (path.empty()) {
    if (!stretches_.empty()) throw std::runtime_error("the cutter offset does not close");
    return;  // the cutter fits nowhere
  }
  // The vertices: each stretch's end, and the polygon about a vertex before it. el[i] is the
  // element of the move ending at v[i + 1].
  std::vector<Vec2> v{node_at_[stretches_[path.front()].from]};
  std::vector<int> el;
  for (const int s : path) {
    const Stretch& st = stretches_[s];
    const Edge& e = edges_[st.edge];
    if (e.kind == Edge::kCircle) {
      const size_t before = v.size();
      around(e.c, sense_ * st.t0, sense_ * (st.t1 - st.t0), r_, v);
      el.insert(el.end(), v.size() - before, e.element);
    }
    v.push_back(node_at_[st.to]);
    el.push_back(e.element);
  }
  if (closed_) {
    // Start at the first stretch's start, or if that is no corner (a front touching the
    // polygon about a vertex) at the last corner before it.
    v.pop_back();
    const size_t m = v.size();
    size_t s = 0;
    for (size_t back = 0; back < m; ++back) {
      const size_t i = (m - back) % m;
      if (!straight_on(v[i] - v[(i + m - 1) % m], v[(i + 1) % m] - v[i])) {
        s = i;
        break;
      }
    }
    std::rotate(v.begin(), v.begin() + static_cast<long>(s), v.end());
    std::rotate(el.begin(), el.begin() + static_cast<long>(s), el.end());
    v.push_back(v.front());
  }
  // Leave out repeated points and points on the straight way from the one before to the one
  // after (where a front touches the polygon about its end vertex).
  out->push_back(v.front());
  for (size_t k = 1; k < v.size(); ++k) {
    if (norm(v[k] - out->back()) <= kMerge) continue;
    if (k + 1 < v.size() && straight_on(v[k] - out->back(), v[k + 1] - v[k])) continue;
    out->push_back(v[k]);
    out_elements->push_back(el[k - 1]);
  }
  if (closed_) out->back() = out->front();  // the path ends exactly where it started
}

// Offsets one chain of chord vertices pts (pts.size() >= 2). Returns the offset vertices
// and, per vertex after the first, the element of the chord it ends.
//
// The cutter may not come nearer than R to a chord: the forbidden region is the union of
// discs of radius R about the chain, and the centre path is its edge on the cutter's side.
// That edge is made of offset segments (each chord's line moved by R along its normal,
// Tamm's normal form set to +-R) and arcs of radius R about convex vertices, and where two
// offset segments cross at a concave corner it turns from one onto the other: neighbouring
// offset lines intersected, the paper's construction. It is computed as the boundary of the
// union: every chord's two offsets and every vertex's circle are cut where they cross, each
// stretch between cuts is kept if it is nowhere nearer than R to a chord, and the kept
// stretches are joined end to end into closed curves (ChainOffset).
//
// Following the offset lines alone goes wrong at concave corners: a chord's offset runs on
// past the crossing and back (a fishtail) up to R into the part. At a sharp corner between
// curved spans the trim R tan(turn / 2) reaches past several chords, whose other joints are
// slightly convex; a chord shorter than its trim (a 1-BLU chord onto a rounded span end that
// turns toward the cutter) lies wholly inside it; in a notch narrower than 2R one wall's
// offset crosses the other wall. On the edge of the union none of that can happen: nothing
// nearer than R to a chord is on it.
void offset_chain(const std::vector<Vec2>& pts, const std::vector<int>& elements, double r,
                  bool left, std::vector<Vec2>* out, std::vector<int>* out_elements) {
  ChainOffset(pts, elements, r, left).run(out, out_elements);
}

}  // namespace

std::vector<Move> offset_moves(GridPoint start, const std::vector<Move>& moves,
                               const CutterOffsetOptions& opt, GridPoint* new_start) {
  std::vector<Move> out;
  out.reserve(moves.size() + 16);
  GridPoint cur = start;
  bool first_chain = true;
  size_t i = 0;
  *new_start = start;
  GridPoint out_cur = start;
  while (i < moves.size()) {
    if (moves[i].rapid) {
      // Aim the rapid at the start of the next offset chain (filled in below).
      out.push_back(moves[i]);
      cur = moves[i].to;
      out_cur = moves[i].to;
      ++i;
      first_chain = false;
      continue;
    }
    // A cutting chain: moves i..j-1.
    size_t j = i;
    std::vector<Vec2> pts{to_vec(cur)};
    std::vector<int> elements;
    while (j < moves.size() && !moves[j].rapid) {
      if (moves[j].kind != MoveKind::kLine)
        throw std::runtime_error("the cutter offset works on chords: use --arcs chords with --cutter-radius");
      pts.push_back(to_vec(moves[j].to));
      elements.push_back(moves[j].element);
      ++j;
    }
    std::vector<Vec2> verts;
    std::vector<int> vel;
    offset_chain(pts, elements, opt.radius, opt.left, &verts, &vel);
    if (!verts.empty()) {
      const GridPoint s = round_to_grid(verts[0]);
      if (first_chain && out.empty()) {
        *new_start = s;
      } else if (!out.empty() && out.back().rapid) {
        out.back().to = s;  // the rapid now ends at the offset start
      } else if (s != out_cur) {
        out.push_back({MoveKind::kLine, s, {}, -1, false, false});
      }
      out_cur = s;
      for (size_t k = 1; k < verts.size(); ++k) {
        const GridPoint g = round_to_grid(verts[k]);
        if (g == out_cur) continue;
        out.push_back({MoveKind::kLine, g, {}, vel[k - 1], true, false});
        out_cur = g;
      }
    }
    first_chain = false;
    cur = moves[j - 1].to;
    i = j;
  }
  return out;
}

}  // namespace ncinterp::firststage
