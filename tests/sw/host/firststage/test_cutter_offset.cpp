// The cutter-centre path, judged by what the cutter leaves, with the independent distance
// measure: the part's surface is the envelope of a disc of radius R moving along the path,
// so (1) no gouge: every point of the path is at least R - delta' from the contour, and
// (2) nothing left: every point of the contour is at most R + delta' from the path (where
// a disc of radius R can reach it at all: not inside a sharp concave corner or a notch
// narrower than the cutter). delta' = tol - budget; the first stage keeps the offset's own
// rounding inside it. Shapes are built here from their parameters and sampled from them.
#include <gtest/gtest.h>

#include "test_helpers.h"

namespace ncinterp::test {
namespace {

using firststage::run_first_stage;

// A contour piece with its own sampler: a line, an arc by centre, radius and angles, or a
// cubic parabola y = k[0] x^3 + k[1] x^2 + k[2] x + k[3] for x from x0 to x1.
struct Piece {
  enum Kind { kLine, kArc, kCubic } kind = kLine;
  P2 a, b;                 // line
  P2 c;                    // arc
  double r = 0, a0 = 0, sweep = 0;
  double k[4] = {0, 0, 0, 0}, x0 = 0, x1 = 0;  // cubic parabola
  P2 at(double s) const {
    switch (kind) {
      case kLine: return {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)};
      case kArc: return {c.x + r * std::cos(a0 + s * sweep), c.y + r * std::sin(a0 + s * sweep)};
      case kCubic: {
        const double x = x0 + s * (x1 - x0);
        return {x, ((k[0] * x + k[1]) * x + k[2]) * x + k[3]};
      }
    }
    return {};
  }
  double length() const {
    if (kind == kLine) return std::hypot(b.x - a.x, b.y - a.y);
    if (kind == kArc) return std::fabs(sweep) * r;
    double len = 0;  // only sizes the sampling: a fine polyline is enough
    for (int i = 0; i < 1000; ++i) {
      const P2 p = at(i / 1000.0), q = at((i + 1) / 1000.0);
      len += std::hypot(q.x - p.x, q.y - p.y);
    }
    return len;
  }
  Segment segment() const {
    if (kind == kLine) return Segment::line({a.x, a.y}, {b.x, b.y});
    if (kind == kArc) return Segment::arc({c.x, c.y}, r, a0, sweep);
    return Segment::cubic_parabola(k[0], k[1], k[2], k[3], x0, x1);
  }
};

Piece line(P2 a, P2 b) {
  Piece p;
  p.a = a;
  p.b = b;
  return p;
}
Piece arc(P2 c, double r, double a0, double sweep) {
  Piece p;
  p.kind = Piece::kArc;
  p.c = c;
  p.r = r;
  p.a0 = a0;
  p.sweep = sweep;
  return p;
}
Piece cubic(const double (&k)[4], double x0, double x1) {
  Piece p;
  p.kind = Piece::kCubic;
  for (int i = 0; i < 4; ++i) p.k[i] = k[i];
  p.x0 = x0;
  p.x1 = x1;
  return p;
}

Contour contour_of_pieces(const std::vector<Piece>& pieces) {
  std::vector<Segment> segs;
  for (const Piece& p : pieces) segs.push_back(p.segment());
  const P2 s = pieces.front().at(0.0);
  return contour_of({s.x, s.y}, segs);
}

std::vector<P2> sample_pieces(const std::vector<Piece>& pieces, double step) {
  std::vector<P2> out;
  for (const Piece& p : pieces) {
    const long n = static_cast<long>(p.length() / step) + 1;
    for (long i = 0; i <= n; ++i) out.push_back(p.at(static_cast<double>(i) / n));
  }
  return out;
}

// Points every `step` along each chain.
std::vector<P2> densify(const std::vector<std::vector<P2>>& chains, double step) {
  std::vector<P2> out;
  for (const auto& ch : chains)
    for (size_t j = 0; j + 1 < ch.size(); ++j) {
      const long n = static_cast<long>(std::hypot(ch[j + 1].x - ch[j].x, ch[j + 1].y - ch[j].y) / step) + 1;
      for (long q = 0; q <= n; ++q) {
        const double f = static_cast<double>(q) / n;
        out.push_back({ch[j].x + f * (ch[j + 1].x - ch[j].x), ch[j].y + f * (ch[j + 1].y - ch[j].y)});
      }
    }
  return out;
}

struct OffsetCheck {
  DistanceRange contour_to_path;  // over the contour samples that a disc can reach
  DistanceRange path_to_contour;
  bool closes = true;             // a closed contour's offset path ends where it starts
};

// `unreachable(p)`: contour points the cutter cannot reach (left out of the upper bound).
template <class Unreachable>
OffsetCheck check_offset(const std::vector<Piece>& pieces, const FirstStageOptions& o,
                         Unreachable unreachable) {
  const Contour c = contour_of_pieces(pieces);
  const FirstStageResult r = run_first_stage(c, o);
  const auto chains = path_chains_mm(r.start, r.moves, o.blu_mm);
  const std::vector<P2> contour = sample_pieces(pieces, 0.01);
  std::vector<P2> reachable;
  for (const P2& p : contour)
    if (!unreachable(p)) reachable.push_back(p);
  OffsetCheck k;
  k.contour_to_path = distance_range(reachable, chains);
  k.path_to_contour = distance_range(densify(chains, 0.01), {contour});
  if (c.closed()) k.closes = r.moves.back().to == r.start;
  return k;
}

void expect_band(const OffsetCheck& k, const FirstStageOptions& o, bool upper = true) {
  const double dprime = o.tol_mm - o.budget_blu * o.blu_mm, radius = o.cutter_radius_mm;
  const double slack = 1e-6;
  EXPECT_GE(k.path_to_contour.min, radius - dprime - slack)
      << "gouge at (" << k.path_to_contour.at_min.x << ", " << k.path_to_contour.at_min.y << ")";
  EXPECT_GE(k.contour_to_path.min, radius - dprime - slack)
      << "gouge at (" << k.contour_to_path.at_min.x << ", " << k.contour_to_path.at_min.y << ")";
  if (upper)
    EXPECT_LE(k.contour_to_path.max, radius + dprime + slack)
        << "left uncut at (" << k.contour_to_path.at_max.x << ", " << k.contour_to_path.at_max.y << ")";
  EXPECT_TRUE(k.closes);
}

const auto kReachable = [](P2) { return false; };

class Offset : public ::testing::TestWithParam<int> {
 protected:
  FirstStageOptions options(double radius, bool left) const {
    FirstStageOptions o;
    o.method = GetParam();
    o.cutter_radius_mm = radius;
    o.side_left = left;
    return o;
  }
};

TEST_P(Offset, CircleOutsideAndInside) {
  // Counter-clockwise circle r = 20: the cutter right of travel is outside, left inside.
  const std::vector<Piece> circle{arc({0, 0}, 20.0, 0.0, 2 * M_PI)};
  for (const bool left : {false, true}) {
    SCOPED_TRACE(left ? "inside" : "outside");
    const FirstStageOptions o = options(3.0, left);
    expect_band(check_offset(circle, o, kReachable), o);
  }
}

TEST_P(Offset, CubicWithInflectionBothSides) {
  // An open S-curve built from two tangent arcs (convex, then concave): radii 15 and 10.
  const std::vector<Piece> s{arc({0, 15}, 15.0, -M_PI / 2, 1.2), arc({25 * std::sin(1.2), 15 - 25 * std::cos(1.2)}, 10.0, M_PI / 2 + 1.2, -1.5)};
  for (const bool left : {false, true}) {
    SCOPED_TRACE(left ? "left" : "right");
    const FirstStageOptions o = options(4.0, left);
    expect_band(check_offset(s, o, kReachable), o);
  }
}

TEST_P(Offset, PolygonWithConvexAndConcaveCorners) {
  // L-shaped plate, counter-clockwise; (15, 15) is its concave corner. Outside milling
  // (cutter right): the convex corners are 90-degree turns (offset lines intersected), the
  // concave corner leaves material a disc cannot reach (left out of the upper bound).
  // Inside milling (a pocket, cutter left): the roles swap.
  const P2 v[] = {{0, 0}, {40, 0}, {40, 15}, {15, 15}, {15, 30}, {0, 30}, {0, 0}};
  std::vector<Piece> l;
  for (int k = 0; k < 6; ++k) l.push_back(line(v[k], v[k + 1]));
  const double radius = 3.0;
  const auto near = [&](P2 p, P2 corner) { return std::hypot(p.x - corner.x, p.y - corner.y) < 2 * radius; };
  {
    const FirstStageOptions o = options(radius, false);
    expect_band(check_offset(l, o, [&](P2 p) { return near(p, v[3]); }), o);
  }
  {
    const FirstStageOptions o = options(radius, true);
    expect_band(check_offset(l, o, [&](P2 p) {
      for (int k = 0; k < 6; ++k)
        if (k != 3 && near(p, v[k])) return true;
      return false;
    }), o);
  }
}

TEST_P(Offset, SharpConvexCornerGoesAroundNotFarOut) {
  // A thin triangle, counter-clockwise, cutter outside: its tip turns by ~160 degrees. The
  // centre path goes around the tip on a polygon about the circle of radius R (each piece
  // turning <= 90 degrees): no point of the path is farther than R * sqrt(2) from the tip.
  const P2 v[] = {{0, 0}, {60, 5}, {0, 10}, {0, 0}};
  std::vector<Piece> t;
  for (int k = 0; k < 3; ++k) t.push_back(line(v[k], v[k + 1]));
  const FirstStageOptions o = options(2.0, false);
  const OffsetCheck k = check_offset(t, o, kReachable);
  expect_band(k, o);
  EXPECT_LE(k.path_to_contour.max, 2.0 * std::sqrt(2.0) + 0.01);
}

TEST_P(Offset, NotchNarrowerThanTheCutterIsNotGouged) {
  // A 40 x 20 plate with a semicircular notch of radius 2 in its top side, cut from outside
  // with R = 3: the cutter cannot enter the notch, so the offset must drop the notch's
  // chords instead of cutting into the plate beside it.
  const std::vector<Piece> plate{line({0, 0}, {40, 0}), line({40, 0}, {40, 20}), line({40, 20}, {22, 20}),
                                 arc({20, 20}, 2.0, 0.0, -M_PI), line({18, 20}, {0, 20}), line({0, 20}, {0, 0})};
  const FirstStageOptions o = options(3.0, false);
  expect_band(check_offset(plate, o, [](P2 p) { return std::hypot(p.x - 20, p.y - 20) < 6.5; }), o);
}

TEST_P(Offset, ConcaveCornerBetweenCurvedSpansIsTrimmed) {
  // Soak seed 8 (docs/verification.md section 8): two cubic parabolas of its chain, each
  // bending gently away from the cutter on the left, meet in a valley where the path turns
  // toward the cutter by 93 degrees. Every joint between chords of a span is slightly
  // convex; the corner trims both neighbouring offset lines by R tan(turn / 2) = 3.7 mm,
  // past several chords (W = 10 keeps them under 1.03 mm). Those chords must be dropped, not
  // followed past the corner and back (the fishtail that cut 3.56 mm into the part). Cut
  // from the right the same corner is convex (turn > 90 degrees: the polygon around it).
  const double xc = 83.675252134354409;  // the corner
  const double k3[4] = {-3.0175072969270059e-05, -0.0022015105485997796, -0.3131163176584576,
                        67.237398792817615};
  const double k4[4] = {-0.00017691956922019807, 0.036745173841388284, -1.5853258209999175,
                        -13.026038865453671};
  const std::vector<Piece> valley{cubic(k3, 60.768467225358975, xc), cubic(k4, xc, 108.18048868741303)};
  const P2 corner = valley[1].at(0.0);
  const auto slope = [&](const double (&k)[4]) { return (3 * k[0] * xc + 2 * k[1]) * xc + k[2]; };
  const double turn = std::atan(slope(k4)) - std::atan(slope(k3));
  ASSERT_GT(turn, M_PI / 2);  // toward the left: concave for a cutter on the left
  const double radius = 3.56;
  for (const bool left : {true, false}) {
    SCOPED_TRACE(left ? "left (concave corner)" : "right (convex corner)");
    FirstStageOptions o = options(radius, left);
    o.tol_mm = 0.005;
    o.width = 10;
    // A disc of radius R in the valley touches each side about R tan(turn / 2) from the
    // corner (a little nearer, as the sides fall away from it): nearer is out of its reach.
    const double reach = 1.1 * radius * std::tan(turn / 2);
    expect_band(check_offset(valley, o, [&](P2 p) {
      return left && std::hypot(p.x - corner.x, p.y - corner.y) < reach;
    }), o);
  }
}

TEST_P(Offset, ShortChordTurningTowardTheCutterLeavesNothing) {
  // Soak seed 839: the last cubic parabola of its chain, then the part's side straight down
  // (a convex corner for the cutter on the left). At BLU 0.01 the chain's chords end 1 BLU
  // diagonally before the rounded span end, and that 1-BLU chord turns toward the cutter by
  // about 57 degrees. Its offset line, trimmed by R tan(28.5 deg) = 1.5 mm, starts far beyond
  // the chord, so following it keeps the cutter off the chord before it: 0.14 mm left (tol
  // 0.05). The cutter must go from that chord's offset around the corner instead.
  const double k5[4] = {0.00060606433606152715, -0.23696115456914191, 30.662425696170882,
                        -1321.8866380302138};
  const double x0 = 116.87443475377074, x1 = 134.30420270257304;
  const Piece curve = cubic(k5, x0, x1);
  const P2 end = curve.at(1.0);
  const std::vector<Piece> chain{curve, line(end, {end.x, end.y - 10.0})};
  FirstStageOptions o = options(2.76, true);
  o.tol_mm = 0.05;
  o.blu_mm = 0.01;
  expect_band(check_offset(chain, o, kReachable), o);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, Offset, ::testing::Values(1, 2, 3));

}  // namespace
}  // namespace ncinterp::test
