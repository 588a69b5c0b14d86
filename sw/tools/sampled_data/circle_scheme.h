// K1..K7: the paper's circle interpolators, one period at a time, each coded exactly as
// paper 003 writes it, on any arithmetic (float_arith.h, fixed_arith.h).
// Idea: the circle about the origin solves X' = Y, Y' = -X; each method is one way of
// integrating that over a period with step h = V T / R (h > 0 clockwise). Formulas, with
// (X, Y) the current point, (X-, Y-) the one before and (X+, Y+) the next:
//   K1  X+ = X + hY;                 Y+ = Y - hX                          (Euler)
//   K2  Xm = X + 0.5 dX;  Ym = Y + 0.5 dY;  X+ = X + h Ym;  Y+ = Y - h Xm
//       dX, dY = the increments of the last period (X - X-, Y - Y-). This is the only
//       reading under which K2 is "not self-starting" and costs "one shift and one add
//       per coordinate" more than K1, as the paper says. (Were dX = hY, K2 would be K7
//       term by term.)
//   K3  X+ = X- + 2hY;               Y+ = Y- - 2hX                        (two-step)
//   K4  X+ = X + hY;                 Y+ = Y - h X+                        (new X at once)
//   K5  K4 on even periods (eq. 3); on odd periods Y first: Y+ = Y - hX; X+ = X + h Y+
//   K6  Xm = X + 0.5hY;  Y+ = Y - 2h Xm;  X+ = Xm + 0.5h Y+              (one period)
//   K7  X+ = X + hY - 0.5h^2 X;      Y+ = Y - hX - 0.5h^2 Y               (Taylor)
// K2 and K3 need (X-, Y-): their first period is one period of the starter method
// (method.h, Starter), after which they run as written. The constants h, 0.5h, 2h and
// 0.5h^2 are formed once per arc, as a controller would before interpolating.
#pragma once
#include <cstdint>
#include <stdexcept>

#include "method.h"

namespace ncinterp::sampled {

template <class Arith>
class CircleScheme {
 public:
  using Value = typename Arith::Value;
  struct Point {
    Value x, y;
  };

  CircleScheme(Method method, double h, Starter starter, Arith& arith)
      : method_(method),
        starter_(starter),
        a_(arith),
        h_(arith.coef(h)),
        half_h_(arith.coef(0.5L * h)),
        two_h_(arith.coef(2.0L * h)),
        half_h2_(arith.coef(0.5L * h * h)) {
    if (method == Method::kL1) throw std::invalid_argument("L1 is the line interpolator (line_scheme.h)");
  }

  // Starts at p, the first reference point (relative to the centre).
  void start(Point p) {
    cur_ = p;
    has_prev_ = false;
    periods_ = 0;
  }

  // Starts at p with the point one period before it known (K2 and K3 then need no
  // starter; the one-step methods ignore it). Used to measure a single period from an
  // exact history.
  void start(Point previous, Point p) {
    start(p);
    prev_ = previous;
    has_prev_ = true;
    dx_ = a_.sub(p.x, previous.x);
    ydec_ = a_.sub(previous.y, p.y);
  }

  // One interpolation period; returns the new reference point.
  Point step() {
    Point next{};
    switch (method_) {
      case Method::kK1: next = euler(cur_); break;
      case Method::kK2: next = has_prev_ ? improved_polygon() : first_period(); break;
      case Method::kK3: next = has_prev_ ? two_step() : first_period(); break;
      case Method::kK4: next = x_then_y(cur_); break;
      case Method::kK5: next = periods_ % 2 == 0 ? x_then_y(cur_) : y_then_x(cur_); break;
      case Method::kK6: next = k6(cur_); break;
      case Method::kK7: next = taylor(cur_); break;
      case Method::kL1: break;
    }
    prev_ = cur_;
    has_prev_ = true;
    cur_ = next;
    ++periods_;
    return next;
  }

  Point point() const { return cur_; }

 private:
  Point euler(Point p) { return {a_.add(p.x, a_.mul(h_, p.y)), a_.sub(p.y, a_.mul(h_, p.x))}; }

  Point taylor(Point p) {
    return {a_.sub(a_.add(p.x, a_.mul(h_, p.y)), a_.mul(half_h2_, p.x)),
            a_.sub(a_.sub(p.y, a_.mul(h_, p.x)), a_.mul(half_h2_, p.y))};
  }

  // K2 / K3 without a previous point: one period of the starter, and K2's increments.
  Point first_period() {
    const Point next = starter_ == Starter::kK1 ? euler(cur_) : taylor(cur_);
    if (method_ == Method::kK2) {
      dx_ = a_.sub(next.x, cur_.x);
      ydec_ = a_.sub(cur_.y, next.y);
    }
    return next;
  }

  // K2. The increment of Y is kept as the decrement ydec = Y- - Y (Y falls when h > 0),
  // so Ym = Y + 0.5 dY is Y - 0.5 ydec: the same number, no negation needed.
  Point improved_polygon() {
    const Value xm = a_.add(cur_.x, a_.half(dx_));
    const Value ym = a_.sub(cur_.y, a_.half(ydec_));
    dx_ = a_.mul(h_, ym);
    ydec_ = a_.mul(h_, xm);
    return {a_.add(cur_.x, dx_), a_.sub(cur_.y, ydec_)};
  }

  Point two_step() { return {a_.add(prev_.x, a_.mul(two_h_, cur_.y)), a_.sub(prev_.y, a_.mul(two_h_, cur_.x))}; }

  Point x_then_y(Point p) {  // K4; K5's equations (3)
    const Value x = a_.add(p.x, a_.mul(h_, p.y));
    return {x, a_.sub(p.y, a_.mul(h_, x))};
  }

  Point y_then_x(Point p) {  // K5's equations (4)
    const Value y = a_.sub(p.y, a_.mul(h_, p.x));
    return {a_.add(p.x, a_.mul(h_, y)), y};
  }

  Point k6(Point p) {
    const Value xm = a_.add(p.x, a_.mul(half_h_, p.y));
    const Value y = a_.sub(p.y, a_.mul(two_h_, xm));
    return {a_.add(xm, a_.mul(half_h_, y)), y};
  }

  Method method_;
  Starter starter_;
  Arith& a_;
  typename Arith::Coef h_, half_h_, two_h_, half_h2_;
  Point cur_{}, prev_{};  // the current reference point and the one before it
  bool has_prev_ = false;
  Value dx_{}, ydec_{};  // K2: X - X-, Y- - Y
  uint64_t periods_ = 0;
};

}  // namespace ncinterp::sampled
