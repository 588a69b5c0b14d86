// Clocking a bare verilated module in a module-level lock-step test: one clock (the rising
// edge, then the falling one, each evaluated) and a synchronous reset.
// Idea: the tests that drive a verilated module without the VerilatedInterp wrapper all take
// these two steps; the reset settles the model with the clock low first, since Verilator
// sees no edge on the first eval().
#pragma once

namespace ncinterp::test {

template <typename Model>
void clock_edge(Model& m) {
  m.clk_i = 1;
  m.eval();
  m.clk_i = 0;
  m.eval();
}

template <typename Model>
void reset(Model& m) {
  m.rst_ni = 0;
  m.clk_i = 0;
  m.eval();
  clock_edge(m);
  m.rst_ni = 1;
  m.eval();
}

}  // namespace ncinterp::test
