// CSV and text tables of the methods study (see methods_report.h).
#include "methods_report.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <sstream>

#include "paper_claims.h"

namespace ncinterp::sampled {
namespace {

std::string format(const char* fmt, ...) {
  char buf[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, args);
  va_end(args);
  return buf;
}

// A CSV number: empty when it does not apply (NaN).
std::string csv_number(double v) { return std::isnan(v) ? "" : format("%.9g", v); }

const char* claim_quantity(ClaimedQuantity q) {
  return q == ClaimedQuantity::kStepError ? "one period" : "quarter";
}

const MethodSummary& summary_of(const Study& s, Method m) {
  for (const MethodSummary& x : s.summaries)
    if (x.method == m) return x;
  return s.summaries.front();
}

// The h values shown in the text table: all of them when few, else the powers of ten.
std::vector<double> shown_hs(const std::vector<double>& hs) {
  if (hs.size() <= 5) return hs;
  std::vector<double> shown;
  for (double h : hs)
    if (std::fabs(std::log10(h) - std::round(std::log10(h))) < 1e-9) shown.push_back(h);
  return shown.empty() ? std::vector<double>{hs.front(), hs.back()} : shown;
}

const StudyRow* row_at(const Study& s, Method m, double radius, double h) {
  for (const StudyRow& r : s.rows)
    if (r.method == m && r.radius == radius && r.h == h) return &r;
  return nullptr;
}

std::string fit_text(const OrderFit& f) {
  if (!f.valid) return "no fit (needs two values of h)";
  return format("p %.2f c %.3g (h %.0e..%.0e, %d pts, resid %.2f dec)", f.order, f.constant, f.h_min, f.h_max,
                f.points, f.max_residual_decades);
}

std::string ops_text(const OpCount& o) {
  return format("%llu mul %llu add%s", static_cast<unsigned long long>(o.mul), static_cast<unsigned long long>(o.add),
                o.shift ? format(" %llu shift", static_cast<unsigned long long>(o.shift)).c_str() : "");
}

std::string verdict(double p_claim, double c_claim, const OrderFit& fit) {
  if (!fit.valid) return "no fit";
  if (std::fabs(fit.order - p_claim) > kOrderTolerance) return format("DISAGREES: order %.2f, not %.0f", fit.order, p_claim);
  if (std::isnan(c_claim)) return "agrees (order)";
  const double ratio = fit.constant / c_claim;
  if (std::fabs(ratio - 1) > kConstantTolerance) return format("DISAGREES: constant is %.2f x the claim", ratio);
  return format("agrees (constant %.3f x the claim)", ratio);
}

}  // namespace

std::string methods_csv(const Study& study) {
  std::ostringstream out;
  out << "method,radius_mm,h,periods,error_mm,path_error_mm,end_error_mm,worst_angle_deg,"
         "first_turn_error_mm,last_turn_error_mm,drift_per_turn_mm,drifts,local_error_rel,paper_error_mm,"
         "roundoff_limited,word_bits,quantum_mm,fixed_error_mm,fixed_minus_double_mm,"
         "mul_per_period,add_per_period,shift_per_period\n";
  for (const StudyRow& r : study.rows) {
    const bool circle = r.method != Method::kL1;
    out << method_name(r.method) << ',' << csv_number(r.radius) << ',' << csv_number(r.h) << ',' << r.periods << ','
        << csv_number(r.error) << ',' << csv_number(r.path_error) << ',' << csv_number(r.end_error) << ','
        << csv_number(r.worst_angle_deg) << ',' << csv_number(r.first_turn_error) << ','
        << csv_number(r.last_turn_error) << ',' << csv_number(r.drift_per_turn) << ','
        << (circle ? (r.drifts ? "1" : "0") : "") << ',' << csv_number(r.local_error) << ','
        << csv_number(r.paper_error) << ',' << (r.roundoff_limited ? 1 : 0) << ',' << study.config.word_bits << ','
        << csv_number(r.quantum) << ',' << csv_number(r.fixed_error) << ',' << csv_number(r.fixed_minus_double)
        << ',' << r.ops_per_period.mul << ',' << r.ops_per_period.add << ',' << r.ops_per_period.shift << '\n';
  }
  return out.str();
}

std::string methods_text(const Study& study, const std::vector<ComparisonRow>& comparison, double blu_mm) {
  const StudyConfig& cfg = study.config;
  std::ostringstream out;
  out << "Reference-word interpolators of paper 003. K1..K7: a quarter circle from (R, 0) clockwise; L1: a line of\n"
      << format("length R at %.0f deg. %zu radii, %zu values of h, %d turns for the drift, fixed point in %d-bit words;\n",
                kLineAngleDeg, cfg.radii_mm.size(), cfg.hs.size(), cfg.turns, cfg.word_bits)
      << "K2 and K3 make their first period with " << (cfg.starter == Starter::kK1 ? "K1" : "K7") << ".\n\n";

  // 1. Measured errors beside the paper's formula.
  const double r0 = cfg.radii_mm.front();
  const std::vector<double> hs = shown_hs(cfg.hs);
  out << format("Largest radial error over a quarter circle / R in double (R = %g mm; '*' = round-off limited), and\n"
                "the paper's formula at the same h. L1: distance of the last point from the end, and largest\n"
                "distance from the line, / L:\n",
                r0);
  out << format("%-7s", "method");
  for (double h : hs) out << format(" %11s", format("h=%.0e", h).c_str());
  out << "  | paper:";
  for (double h : hs) out << format(" %9s", format("h=%.0e", h).c_str());
  out << "\n";
  // One line: a measured quantity / R at each shown h, then the paper's formula / R.
  const auto line = [&](const char* label, Method m, double (*value)(const StudyRow&), bool mark_roundoff) {
    out << format("%-7s", label);
    for (double h : hs) {
      const StudyRow* r = row_at(study, m, r0, h);
      out << format(" %10.3e%s", r ? value(*r) / r->radius : NAN, mark_roundoff && r && r->roundoff_limited ? "*" : " ");
    }
    out << "  |       ";
    for (double h : hs) {
      const StudyRow* r = row_at(study, m, r0, h);
      out << (r && !std::isnan(r->paper_error) ? format(" %9.3e", r->paper_error / r->radius) : format(" %9s", "-"));
    }
    out << "\n";
  };
  line("L1 end", Method::kL1, [](const StudyRow& r) { return r.end_error; }, false);
  line("L1 line", Method::kL1, [](const StudyRow& r) { return r.error; }, true);
  for (Method m : kCircleMethods) line(method_name(m), m, [](const StudyRow& r) { return r.error; }, true);

  // 2. Fitted laws e = c h^p R.
  out << "\nFitted error laws e = c h^p R (log-log least squares over every radius; round-off limited rows left out):\n";
  for (Method m : kAllMethods) {
    const MethodSummary& s = summary_of(study, m);
    const bool all_roundoff = s.roundoff_rows == s.rows;
    out << format("%-3s %-22s %s: %s\n", method_name(m), ops_text(s.ops_per_period).c_str(),
                  m == Method::kL1 ? "line" : "quarter",
                  all_roundoff ? format("exact up to round-off (all %d rows)", s.rows).c_str() : fit_text(s.error).c_str());
    if (m == Method::kL1) continue;
    out << format("%-26s one period: %s\n", "", fit_text(s.local).c_str());
    out << format("%-26s drift/turn: %s\n", "",
                  s.drifting_rows ? format("%s, %d of %d rows drift", fit_text(s.drift).c_str(), s.drifting_rows, s.rows).c_str()
                                  : "none: the error of the last turn is that of the first");
  }

  // 3. The paper's claims.
  out << format("\nThe paper's claims (agrees: order within %.1f and constant within %.0f%%):\n", kOrderTolerance,
                kConstantTolerance * 100);
  for (const PaperClaim& c : paper_claims()) {
    const MethodSummary& s = summary_of(study, c.method);
    const OrderFit& fit = c.quantity == ClaimedQuantity::kStepError ? s.local : s.error;
    out << format("%-3s %-10s %-38s p %.0f c %-7s measured %-14s %s\n", method_name(c.method), claim_quantity(c.quantity),
                  c.formula, c.order, std::isnan(c.constant) ? "-" : format("%.3f", c.constant).c_str(),
                  fit.valid ? format("p %.2f c %.3f", fit.order, fit.constant).c_str() : "-",
                  verdict(c.order, c.constant, fit).c_str());
  }

  // 4. Against the hardware circle DDA.
  out << format("\nHolding a full quadrant to 1 BLU (%g mm): hardware circle DDA (golden model) against each method at\n"
                "the largest h whose double path (chords included) is within 0.5 BLU, in the shortest word keeping it\n"
                "within 1 BLU:\n",
                blu_mm);
  for (const ComparisonRow& row : comparison) {
    const DdaQuadrant& d = row.dda;
    out << format("R = %lld BLU (%g mm)\n", static_cast<long long>(row.radius_blu), row.radius_blu * blu_mm);
    out << format("  %-6s %9s %10s %-22s %5s %-22s\n", "", "h", "steps", "operations per step", "bits", "error (BLU)");
    out << format("  %-6s %9s %10llu %-22s %5u %.3f at the pulses\n", "DDA", format("2^-%u", d.k).c_str(),
                  static_cast<unsigned long long>(d.iterations),
                  format("%.2f add, 0 mul", d.additions_per_iteration()).c_str(), d.k, d.max_radial_error_blu);
    for (const SampledForOneBlu& m : row.methods) {
      if (!m.reached) {
        out << format("  %-6s no h >= 1e-6 holds 0.5 BLU\n", method_name(m.method));
        continue;
      }
      out << format("  %-6s %9.2e %10llu %-22s %5s %.3f double, %s\n", method_name(m.method), m.h,
                    static_cast<unsigned long long>(m.periods), ops_text(m.ops_per_period).c_str(),
                    m.word_bits ? format("%d", m.word_bits).c_str() : ">62", m.path_error_double_blu,
                    m.word_bits ? format("%.3f fixed", m.path_error_fixed_blu).c_str() : "-");
    }
  }
  return out.str();
}

}  // namespace ncinterp::sampled
