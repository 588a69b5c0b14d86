// The reference-word interpolators of paper 003 (V. V. Erokhin, 2017) that this library
// implements: L1 for a straight line and K1..K7 for a circle, and the choice of the first
// step for K2 and K3, which the paper says are not self-starting.
// Idea: a reference-word interpolator computes, once per interpolation period T, the next
// point of the path (X, Y relative to the circle's centre) by a numerical integration step
// of X' = Y, Y' = -X with step h = V T / R; the servo gets the increment of each period.
#pragma once
#include <optional>
#include <string_view>

namespace ncinterp::sampled {

enum class Method { kL1, kK1, kK2, kK3, kK4, kK5, kK6, kK7 };

inline constexpr Method kAllMethods[] = {Method::kL1, Method::kK1, Method::kK2, Method::kK3,
                                         Method::kK4, Method::kK5, Method::kK6, Method::kK7};
inline constexpr Method kCircleMethods[] = {Method::kK1, Method::kK2, Method::kK3, Method::kK4,
                                            Method::kK5, Method::kK6, Method::kK7};

const char* method_name(Method m);         // "L1", "K1", ...
const char* method_description(Method m);  // "Euler", "Taylor", ...

// K2 and K3 use the point before the current one. The paper: "on the first step some other
// method has to be used". The first point after the start is computed by one period of
// this self-starting method; from then on the method runs as written.
enum class Starter { kK1, kK7 };

std::optional<Starter> parse_starter(std::string_view text);

}  // namespace ncinterp::sampled
