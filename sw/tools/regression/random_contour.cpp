// Random part contours (see random_contour.h).
#include "random_contour.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "inputs/contour_inputs.h"

namespace ncinterp::regression {
namespace {

using firststage::Vec2;

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
int uniform_int(std::mt19937_64& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}
bool chance(std::mt19937_64& rng, double p) { return uniform(rng, 0.0, 1.0) < p; }

std::string num(double v, int digits = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}
double round_to(double v, int digits = 4) {
  const double s = std::pow(10.0, digits);
  return std::round(v * s) / s;
}
std::string exact(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Closed star-shaped polygon with fillets (convex and concave), a rapid to a hole cut as a
// full circle (clockwise, as part.nc). Absolute G-code.
std::string random_part(std::mt19937_64& rng) {
  const int n = uniform_int(rng, 5, 8);
  const Vec2 c{50, 50};
  std::vector<Vec2> v;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * (i + uniform(rng, -0.25, 0.25)) / n;
    const double r = uniform(rng, 22, 40);
    v.push_back({round_to(c.x + r * std::cos(a)), round_to(c.y + r * std::sin(a))});
  }
  std::ostringstream g;
  g << "%\n(random part: " << n << " corners, fillets, a hole)\nG21 G90 G17\n";
  const Vec2 start = 0.5 * (v[0] + v[1]);
  g << "G0 X" << num(start.x) << " Y" << num(start.y) << "\n";
  for (int k = 1; k <= n; ++k) {
    const Vec2 prev = v[(k - 1) % n], at = v[k % n], next = v[(k + 1) % n];
    const Vec2 din = unit(at - prev), dout = unit(next - at);
    const double turn = std::atan2(cross(din, dout), dot(din, dout));
    const double room = 0.45 * std::min(norm(at - prev), norm(next - at));
    double rf = uniform(rng, 1.0, 8.0);
    const double t = rf * std::tan(0.5 * std::fabs(turn));
    if (!chance(rng, 0.6) || std::fabs(turn) < 0.05 || t > room) {
      g << "G1 X" << num(at.x) << " Y" << num(at.y) << "\n";
      continue;
    }
    const Vec2 tin{round_to(at.x - t * din.x), round_to(at.y - t * din.y)};
    const Vec2 tout{round_to(at.x + t * dout.x), round_to(at.y + t * dout.y)};
    const Vec2 centre = tin + rf * (turn > 0 ? perp(din) : -1.0 * perp(din));
    g << "G1 X" << num(tin.x) << " Y" << num(tin.y) << "\n";
    g << (turn > 0 ? "G3" : "G2") << " X" << num(tout.x) << " Y" << num(tout.y) << " I"
      << num(round_to(centre.x) - tin.x) << " J" << num(round_to(centre.y) - tin.y) << "\n";
  }
  g << "G1 X" << num(start.x) << " Y" << num(start.y) << "\n";
  const double rh = uniform(rng, 3.0, 8.0);
  g << "G0 X" << num(c.x + rh) << " Y" << num(c.y) << "\n";
  g << "G2 X" << num(c.x + rh) << " Y" << num(c.y) << " I" << num(-rh) << " J0\n";
  g << "M30\n%\n";
  return g.str();
}

// Closing sides below a profile ending at x1: down to `bottom`, back to x0, up to (x0, y0).
std::string closing_lines(double x0, double y0, double x1, double bottom) {
  return ",\n  {\"type\": \"line\", \"to\": [" + exact(x1) + ", " + exact(bottom) + "]}" +
         ",\n  {\"type\": \"line\", \"to\": [" + exact(x0) + ", " + exact(bottom) + "]}" +
         ",\n  {\"type\": \"line\", \"to\": [" + exact(x0) + ", " + exact(y0) + "]}";
}

std::string random_table(std::mt19937_64& rng) {
  const double x0 = uniform(rng, 0, 50), h = uniform(rng, 4, 15);
  const int n = uniform_int(rng, 6, 24);
  const double amp = uniform(rng, 2, 20), wave = uniform(rng, 0.5, 2.0) * n * h,
               phase = uniform(rng, 0, 2 * M_PI), slope = uniform(rng, -0.3, 0.3);
  std::vector<double> y;
  for (int i = 0; i < n; ++i) {
    const double x = i * h;
    y.push_back(round_to(amp * std::sin(2 * M_PI * x / wave + phase) + slope * x, 3));
  }
  const double bottom = *std::min_element(y.begin(), y.end()) - 10.0;
  std::string s = "{\"units\": \"mm\", \"start\": [" + exact(x0) + ", " + exact(y[0]) +
                  "], \"segments\": [\n  {\"type\": \"table\", \"x0\": " + exact(x0) +
                  ", \"h\": " + exact(h) + ", \"y\": [";
  for (int i = 0; i < n; ++i) s += (i ? ", " : "") + exact(y[i]);
  s += "]}" + closing_lines(x0, y[0], x0 + (n - 1) * h, bottom) + "\n]}\n";
  return s;
}

std::string random_cubic_chain(std::mt19937_64& rng) {
  const int pieces = uniform_int(rng, 2, 5);
  const bool smooth = chance(rng, 0.5);
  const double x_start = uniform(rng, -20, 20), y_start = uniform(rng, -10, 10);
  double x = x_start, y = y_start, slope = uniform(rng, -1, 1), low = y;
  std::string segs;
  for (int p = 0; p < pieces; ++p) {
    const double dx = uniform(rng, 10, 40);
    const double c1 = smooth ? slope : uniform(rng, -1, 1);
    const double c2 = uniform(rng, -0.5, 0.5) / dx, c3 = uniform(rng, -0.3, 0.3) / (dx * dx);
    // y = y + c1 (X - x) + c2 (X - x)^2 + c3 (X - x)^3 expanded in powers of X.
    const double a = c3, b = c2 - 3 * c3 * x, c = c1 - 2 * c2 * x + 3 * c3 * x * x,
                 d = y - c1 * x + c2 * x * x - c3 * x * x * x;
    segs += std::string(p ? ",\n" : "") + "  {\"type\": \"cubic\", \"coefficients\": [" + exact(a) +
            ", " + exact(b) + ", " + exact(c) + ", " + exact(d) + "], \"x_to\": " + exact(x + dx) + "}";
    for (int i = 1; i <= 16; ++i) {
      const double u = dx * i / 16;
      low = std::min(low, y + c1 * u + c2 * u * u + c3 * u * u * u);
    }
    const double x1 = x + dx;
    y = ((a * x1 + b) * x1 + c) * x1 + d;
    slope = c1 + 2 * c2 * dx + 3 * c3 * dx * dx;
    x = x1;
  }
  return "{\"units\": \"mm\", \"start\": [" + exact(x_start) + ", " + exact(y_start) +
         "], \"segments\": [\n" + segs + closing_lines(x_start, y_start, x, low - 10.0) + "\n]}\n";
}

// NACA 4-digit (Abbott & von Doenhoff), open trailing edge, cosine spacing, Selig order.
std::string random_airfoil(std::mt19937_64& rng) {
  const int mi = uniform_int(rng, 0, 6), pi = uniform_int(rng, 2, 6), ti = uniform_int(rng, 8, 21);
  const int npts = uniform_int(rng, 41, 121);
  const double m = mi / 100.0, p = pi / 10.0, t = ti / 100.0;
  std::vector<Vec2> upper, lower;
  for (int i = 0; i < npts; ++i) {
    const double x = 0.5 * (1.0 - std::cos(M_PI * i / (npts - 1)));
    const double yt = 5 * t * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x +
                               0.2843 * x * x * x - 0.1015 * x * x * x * x);
    double yc = 0, dyc = 0;
    if (m > 0) {
      if (x < p) yc = m / (p * p) * (2 * p * x - x * x), dyc = 2 * m / (p * p) * (p - x);
      else yc = m / ((1 - p) * (1 - p)) * ((1 - 2 * p) + 2 * p * x - x * x),
           dyc = 2 * m / ((1 - p) * (1 - p)) * (p - x);
    }
    const double th = std::atan(dyc);
    upper.push_back({x - yt * std::sin(th), yc + yt * std::cos(th)});
    lower.push_back({x + yt * std::sin(th), yc - yt * std::cos(th)});
  }
  std::ostringstream s;
  s << "NACA " << mi << pi << (ti < 10 ? "0" : "") << ti << "\n";
  for (int i = npts - 1; i >= 0; --i) s << " " << num(upper[i].x, 7) << "  " << num(upper[i].y, 7) << "\n";
  for (int i = 1; i < npts; ++i) s << " " << num(lower[i].x, 7) << "  " << num(lower[i].y, 7) << "\n";
  return s.str();
}

std::string random_circle(std::mt19937_64& rng) {
  const double r = round_to(uniform(rng, 5, 80), 3), a = uniform(rng, 0, 2 * M_PI);
  const double cx = round_to(uniform(rng, -50, 50), 3), cy = round_to(uniform(rng, -50, 50), 3);
  return "{\"units\": \"mm\", \"start\": [" + exact(cx + r * std::cos(a)) + ", " +
         exact(cy + r * std::sin(a)) + "], \"segments\": [\n  {\"type\": \"arc\", \"center\": [" +
         exact(cx) + ", " + exact(cy) + "], \"direction\": \"" + (chance(rng, 0.5) ? "ccw" : "cw") +
         "\"}\n]}\n";
}

// Smallest radius of curvature of the contour's curved segments (mm; inf without any).
double min_curvature_radius(const firststage::Contour& c) {
  double best = INFINITY;
  for (const firststage::Segment& s : c.segments) {
    if (s.rapid || s.kind() == firststage::SegmentKind::kLine) continue;
    for (int i = 0; i <= 64; ++i) {
      const firststage::CurvePoint p = s.eval(i / 64.0);
      const double sp = norm(p.d1);
      const double k = sp > 0 ? std::fabs(cross(p.d1, p.d2)) / (sp * sp * sp) : 0.0;
      if (k > 0) best = std::min(best, 1.0 / k);
    }
  }
  return best;
}

// Counter-clockwise closed cutting chain (signed area > 0)?
bool counter_clockwise(const firststage::Contour& c) {
  double area = 0.0;
  for (const firststage::Segment& s : c.segments) {
    if (s.rapid) continue;
    for (int i = 0; i < 32; ++i) {
      const Vec2 a = s.point(i / 32.0), b = s.point((i + 1) / 32.0);
      area += cross(a, b);
    }
  }
  return area > 0;
}

}  // namespace

const char* shape_name(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::kPart: return "part";
    case ShapeKind::kTable: return "table";
    case ShapeKind::kCubic: return "cubic";
    case ShapeKind::kAirfoil: return "airfoil";
    case ShapeKind::kCircle: return "circle";
  }
  return "?";
}

GeneratedInput random_input(ShapeKind kind, std::mt19937_64& rng) {
  GeneratedInput in;
  in.kind = kind;
  switch (kind) {
    case ShapeKind::kPart: in.file_name = "part.nc", in.text = random_part(rng); break;
    case ShapeKind::kTable: in.file_name = "table.json", in.text = random_table(rng); break;
    case ShapeKind::kCubic: in.file_name = "cubic.json", in.text = random_cubic_chain(rng); break;
    case ShapeKind::kAirfoil:
      in.file_name = "airfoil.dat", in.text = random_airfoil(rng);
      in.airfoil_chord_mm = std::round(uniform(rng, 50, 200));
      break;
    case ShapeKind::kCircle: in.file_name = "circle.json", in.text = random_circle(rng); break;
  }
  return in;
}

double contour_length_mm(const firststage::Contour& contour) {
  double len = 0.0;
  for (const firststage::Segment& s : contour.segments)
    for (int i = 0; i < 64; ++i) len += norm(s.point((i + 1) / 64.0) - s.point(i / 64.0));
  return len;
}

Case random_case(uint64_t seed, const RandomCaseLimits& limits, GeneratedInput* input_out) {
  std::mt19937_64 rng(seed);
  const ShapeKind kind = static_cast<ShapeKind>(uniform_int(rng, 0, 4));
  GeneratedInput input = random_input(kind, rng);
  Case c;
  c.name = std::to_string(seed) + "-" + shape_name(kind);
  const std::string file = c.name + "." + input.file_name.substr(input.file_name.find('.') + 1);
  input.file_name = file;
  switch (firststage::input_kind_of(file)) {
    case firststage::InputKind::kJson: c.contour = firststage::parse_json_contour(input.text, file); break;
    case firststage::InputKind::kGcode: c.contour = firststage::parse_gcode(input.text, file); break;
    case firststage::InputKind::kAirfoil:
      c.contour = firststage::parse_airfoil(input.text, file, input.airfoil_chord_mm);
      break;
  }
  firststage::FirstStageOptions& o = c.first_stage;
  o.method = uniform_int(rng, 1, 3);
  const double tols[] = {0.005, 0.01, 0.02, 0.05};
  o.tol_mm = tols[uniform_int(rng, 0, 3)];
  if (o.tol_mm >= 0.05 && chance(rng, 0.3)) o.blu_mm = 0.01;
  const unsigned widths[] = {10, 12, 16};
  o.width = widths[uniform_int(rng, 0, 2)];
  const bool has_arcs = std::any_of(c.contour.segments.begin(), c.contour.segments.end(),
                                    [](const firststage::Segment& s) { return s.is_arc(); });
  o.arcs_circle = limits.arcs_circle_allowed && has_arcs && chance(rng, 0.5);
  // A cutter no larger than half the tightest curvature (so the centre can follow the
  // equidistant everywhere), on the outside of the closed profile.
  const double rmin = min_curvature_radius(c.contour);
  if (limits.cutter_allowed && !o.arcs_circle && c.contour.closed() && chance(rng, 0.3)) {
    const double cap = std::min({5.0, 0.5 * rmin, kind == ShapeKind::kPart ? 2.5 : 5.0});
    if (cap >= 0.5) {
      o.cutter_radius_mm = std::round(uniform(rng, 0.5, cap) * 100) / 100;
      // Outside: the part is on the left of a counter-clockwise outline, so the cutter is
      // on the right. The part's hole is clockwise: right is inside the hole, also correct.
      o.side_left = !counter_clockwise(c.contour);
      if (kind == ShapeKind::kPart) o.side_left = false;
    }
  }
  const double length = contour_length_mm(c.contour);
  o.feed_mm_min = std::max(10.0, length / limits.seconds * 60.0);
  c.check.clock_hz = 1e6;
  c.check.reader_cps = chance(rng, 0.2) ? 2000.0 : 1e5;
  if (input_out) *input_out = input;
  return c;
}

}  // namespace ncinterp::regression
