// Geometry and checks of a quadrant arc block (see arc_geometry.h).
#include "arc_geometry.h"

#include "bit_length.h"

namespace ncinterp {

namespace {

int sign_of(int64_t v) { return (v > 0) - (v < 0); }

// The votes for one sign of the quadrant (0 = no vote) must not disagree.
bool votes_agree(int a, int b, int c) {
  const bool plus = a > 0 || b > 0 || c > 0;
  const bool minus = a < 0 || b < 0 || c < 0;
  return !(plus && minus);
}

struct Signed {
  int64_t x0, y0, x1, y1, dx, dy;
};

Signed signed_points(const ArcWords& w) {
  Signed s;
  s.x0 = w.i_neg ? int64_t{w.i} : -int64_t{w.i};  // start - centre = -I
  s.y0 = w.j_neg ? int64_t{w.j} : -int64_t{w.j};
  s.dx = w.dx_neg ? -int64_t{w.dx} : int64_t{w.dx};
  s.dy = w.dy_neg ? -int64_t{w.dy} : int64_t{w.dy};
  s.x1 = s.x0 + s.dx;
  s.y1 = s.y0 + s.dy;
  return s;
}

uint64_t magnitude(int64_t v) { return static_cast<uint64_t>(v < 0 ? -v : v); }

}  // namespace

ArcWords ArcWords::from_signed(int64_t dx, int64_t dy, int64_t i, int64_t j, bool ccw) {
  ArcWords w;
  w.dx = static_cast<uint32_t>(magnitude(dx));
  w.dy = static_cast<uint32_t>(magnitude(dy));
  w.i = static_cast<uint32_t>(magnitude(i));
  w.j = static_cast<uint32_t>(magnitude(j));
  w.dx_neg = dx < 0;
  w.dy_neg = dy < 0;
  w.i_neg = i < 0;
  w.j_neg = j < 0;
  w.ccw = ccw;
  return w;
}

bool arc_inside_one_quadrant(const ArcWords& w) {
  const Signed s = signed_points(w);
  if (s.dx == 0 && s.dy == 0) return false;  // a full circle is not one quadrant
  // In the quadrant with signs (sx, sy) a ccw arc has sign(dy) = sx and sign(dx) = -sy;
  // a cw arc the opposite. So the motion votes for the quadrant's signs like the ends do.
  const int x_vote = w.ccw ? sign_of(s.dy) : -sign_of(s.dy);
  const int y_vote = w.ccw ? -sign_of(s.dx) : sign_of(s.dx);
  return votes_agree(sign_of(s.x0), sign_of(s.x1), x_vote) &&
         votes_agree(sign_of(s.y0), sign_of(s.y1), y_vote);
}

bool arc_end_on_circle(uint64_t x0, uint64_t y0, uint64_t x1, uint64_t y1) {
  using i128 = __int128;
  const i128 a = static_cast<i128>(x0) * x0 + static_cast<i128>(y0) * y0;
  const i128 b = static_cast<i128>(x1) * x1 + static_cast<i128>(y1) * y1;
  const i128 e = b - a - 1;
  // |e| < 2^63 for magnitudes < 2^31, so e * e fits in 126 bits.
  return e * e <= 4 * a;
}

ArcGeometry arc_geometry(const ArcWords& w, unsigned inc_width) {
  const Signed s = signed_points(w);
  ArcGeometry g;
  g.x0 = magnitude(s.x0);
  g.y0 = magnitude(s.y0);
  g.x1 = magnitude(s.x1);
  g.y1 = magnitude(s.y1);
  g.cnt_x = w.dx;
  g.cnt_y = w.dy;
  g.grow_x = g.x1 > g.x0;
  g.grow_y = g.y1 > g.y0;
  g.k = bit_length(g.x0 | g.y0 | g.x1 | g.y1);
  const uint64_t limit = (uint64_t{1} << inc_width) - 1;
  if (w.i == 0 && w.j == 0)
    g.error = TapeError::kArcZeroRadius;
  else if (!arc_inside_one_quadrant(w))
    g.error = TapeError::kArcCrossesQuadrant;
  else if (g.x1 > limit || g.y1 > limit)
    g.error = TapeError::kValueTooWide;
  return g;
}

TapeError check_arc(const ArcWords& w, unsigned inc_width) {
  const ArcGeometry g = arc_geometry(w, inc_width);
  if (g.error != TapeError::kNone) return g.error;
  if (!arc_end_on_circle(g.x0, g.y0, g.x1, g.y1)) return TapeError::kArcEndpointOffCircle;
  return TapeError::kNone;
}

}  // namespace ncinterp
