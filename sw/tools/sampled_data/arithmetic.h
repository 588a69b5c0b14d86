// Which arithmetic a run uses (double, long double or B-bit fixed point), and the one
// place that turns that choice into the concrete arithmetic object for the schemes.
// Idea: the measurements (circle_runs.h, line_run.h) are written once as templates; the
// callers (study, comparison, tests, CLI) pass a plain value and never see the templates.
#pragma once
#include "fixed_arith.h"
#include "float_arith.h"

namespace ncinterp::sampled {

struct Arithmetic {
  enum class Kind { kDouble, kLongDouble, kFixed };
  Kind kind = Kind::kDouble;
  int word_bits = 0;  // kFixed only

  static Arithmetic double_precision() { return {Kind::kDouble, 0}; }
  static Arithmetic long_double_precision() { return {Kind::kLongDouble, 0}; }
  static Arithmetic fixed(int word_bits) { return {Kind::kFixed, word_bits}; }
};

// Calls run(arith) with the arithmetic `kind` names. A fixed-point format is placed so that
// magnitudes up to max_abs fit the word (FixedFormat::for_magnitude).
template <class Run>
auto with_arithmetic(Arithmetic kind, double max_abs, Run&& run) {
  switch (kind.kind) {
    case Arithmetic::Kind::kLongDouble: {
      FloatArith<long double> a;
      return run(a);
    }
    case Arithmetic::Kind::kFixed: {
      FixedArith a(FixedFormat::for_magnitude(max_abs, kind.word_bits));
      return run(a);
    }
    case Arithmetic::Kind::kDouble:
      break;
  }
  FloatArith<double> a;
  return run(a);
}

}  // namespace ncinterp::sampled
