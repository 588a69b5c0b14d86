#include <gtest/gtest.h>
#include <iostream>
#include "random_contour.h"

namespace ncinterp::regression {
namespace {

TEST(Regression, Explore) {
  RandomCaseLimits lim;
  int fails = 0;
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    try {
      Case c = random_case(seed, lim);
      const auto out = run_case(c);
      std::string d = describe(c, out);
      if (!out.passed()) { ++fails; std::cout << "method " << c.first_stage.method << " tol " << c.first_stage.tol_mm << " R " << c.first_stage.cutter_radius_mm << " w " << c.first_stage.width << "\n" << d; }
      else std::cout << c.name << " ok " << out.checker->total_error().max * out.blu_mm << "/" << c.first_stage.tol_mm << " R " << c.first_stage.cutter_radius_mm << " " << out.checker->cycles() << " clk " << out.seconds << " s\n";
    } catch (std::exception& e) { ++fails; std::cout << seed << ": " << e.what() << "\n"; }
  }
  std::cout << fails << " fails\n";
}

}  // namespace
}  // namespace ncinterp::regression
