// Plane vectors for the first stage's geometry (mm or BLU, whatever the caller works in).
// Idea: one tiny value type with the few operations the chord and offset math needs.
#pragma once
#include <cmath>

namespace ncinterp::firststage {

struct Vec2 {
  double x = 0.0, y = 0.0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
// Plain sqrt, not std::hypot: coordinates are at most ~1e9 BLU, far from overflow, and
// hypot's care costs a fifth of the chord planner's time.
inline double norm(Vec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }
// Left normal: the vector turned +90 degrees.
inline Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
inline Vec2 unit(Vec2 a) {
  double n = norm(a);
  return n > 0 ? Vec2{a.x / n, a.y / n} : Vec2{0.0, 0.0};
}
// Distance from q to the segment a-b; *t (if given) gets the nearest point's parameter in
// [0, 1] (0 for a segment of zero length).
inline double distance_to_segment(Vec2 q, Vec2 a, Vec2 b, double* t = nullptr) {
  const Vec2 v = b - a;
  const double l2 = dot(v, v);
  double u = l2 > 0 ? dot(q - a, v) / l2 : 0.0;
  u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
  if (t) *t = u;
  return norm(q - (a + u * v));
}

}  // namespace ncinterp::firststage
