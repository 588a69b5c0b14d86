#include <gtest/gtest.h>
#include <iostream>
#include "regression_support.h"

namespace ncinterp::regression {
namespace {

TEST(Regression, Explore) {
  for (std::string f : {"circle_r50.json", "reference_table.json", "naca2412_selig.dat", "naca2412_lednicer.dat", "part.nc"})
  for (int m = 1; m <= 3; ++m) {
  Case c;
  c.name = f + " m" + std::to_string(m);
  c.contour = firststage::read_contour(example_path(f), {});
  c.first_stage.feed_mm_min = 20000;
  c.first_stage.method = m;
  c.check.reader_cps = 1e5;
  try {
  const auto out = run_case(c);
  std::cout << describe(c, out) << out.seconds << " s\n";
  } catch (std::exception& e) { std::cout << c.name << ": " << e.what() << "\n"; }
  }
}

}  // namespace
}  // namespace ncinterp::regression
