// Self-crossings of a tape path (see self_intersection.h): sort and prune over straight
// pieces, proper crossings only.
#include "measure/self_intersection.h"

#include <algorithm>
#include <cmath>

namespace ncinterp::firststage {
namespace {

struct Piece {
  Vec2 a, b;
  int move;
  int sub;  // index of the piece within its move (arcs have several)
  double lo_x() const { return std::min(a.x, b.x); }
  double hi_x() const { return std::max(a.x, b.x); }
};

// Sign of the turn a -> b -> c: long double holds the products of BLU coordinates up to
// 2^31 exactly (64-bit mantissa).
int orientation(Vec2 a, Vec2 b, Vec2 c) {
  const long double v = (static_cast<long double>(b.x) - a.x) * (static_cast<long double>(c.y) - a.y) -
                        (static_cast<long double>(b.y) - a.y) * (static_cast<long double>(c.x) - a.x);
  const long double eps = 1e-9L * (std::fabs(static_cast<long double>(b.x) - a.x) +
                                   std::fabs(static_cast<long double>(b.y) - a.y) + 1.0L);
  return v > eps ? 1 : v < -eps ? -1 : 0;
}

bool proper_crossing(const Piece& p, const Piece& q) {
  return orientation(p.a, p.b, q.a) * orientation(p.a, p.b, q.b) < 0 &&
         orientation(q.a, q.b, p.a) * orientation(q.a, q.b, p.b) < 0;
}

Vec2 crossing_point(const Piece& p, const Piece& q) {
  const Vec2 r = p.b - p.a, s = q.b - q.a;
  const double t = ((q.a.x - p.a.x) * s.y - (q.a.y - p.a.y) * s.x) / (r.x * s.y - r.y * s.x);
  return p.a + t * r;
}

void add_arc(Vec2 from, const Move& m, int index, std::vector<Piece>& out) {
  const Vec2 c = to_vec(m.centre), to = to_vec(m.to);
  const double r = norm(from - c);
  const double a0 = std::atan2(from.y - c.y, from.x - c.x);
  double sweep = std::atan2(to.y - c.y, to.x - c.x) - a0;
  if (m.kind == MoveKind::kArcCcw && sweep <= 0) sweep += 2 * M_PI;
  if (m.kind == MoveKind::kArcCw && sweep >= 0) sweep -= 2 * M_PI;
  constexpr int kPieces = 16;
  Vec2 prev = from;
  for (int k = 1; k <= kPieces; ++k) {
    const double a = a0 + sweep * k / kPieces;
    const Vec2 next = k == kPieces ? to : Vec2{c.x + r * std::cos(a), c.y + r * std::sin(a)};
    out.push_back({prev, next, index, k - 1});
    prev = next;
  }
}

}  // namespace

std::optional<SelfCrossing> find_self_crossing(GridPoint start, const std::vector<Move>& moves,
                                               const std::function<bool(int, int)>& ignore) {
  std::vector<Piece> pieces;
  Vec2 cur = to_vec(start);
  for (size_t i = 0; i < moves.size(); ++i) {
    const Move& m = moves[i];
    if (!m.rapid) {
      if (m.kind == MoveKind::kLine)
        pieces.push_back({cur, to_vec(m.to), static_cast<int>(i), 0});
      else
        add_arc(cur, m, static_cast<int>(i), pieces);
    }
    cur = to_vec(m.to);
  }
  std::sort(pieces.begin(), pieces.end(), [](const Piece& p, const Piece& q) { return p.lo_x() < q.lo_x(); });
  for (size_t i = 0; i < pieces.size(); ++i) {
    const Piece& p = pieces[i];
    for (size_t j = i + 1; j < pieces.size() && pieces[j].lo_x() <= p.hi_x(); ++j) {
      const Piece& q = pieces[j];
      if (std::max(p.a.y, p.b.y) < std::min(q.a.y, q.b.y) || std::max(q.a.y, q.b.y) < std::min(p.a.y, p.b.y))
        continue;
      if (!proper_crossing(p, q)) continue;
      if (ignore && ignore(p.move, q.move)) continue;
      return SelfCrossing{crossing_point(p, q), std::min(p.move, q.move), std::max(p.move, q.move)};
    }
  }
  return std::nullopt;
}

}  // namespace ncinterp::firststage
