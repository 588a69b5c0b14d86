// Module-level lock step of the RTL circle modules against their golden twins, every clock:
// dda_circle (rtl/dda_circle.sv) against CircleDda under random iteration strobes, and
// arc_prepare (checks + dry run, rtl/arc_prepare.sv) against ArcPrepare on good and bad
// arcs, at W = 16 and at W = 6 (where random words hit every check), with either dry run.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <type_traits>
#include <sstream>

#include "Varc_prepare.h"
#include "Varc_prepare_serial.h"
#include "Varc_prepare_serial_w6.h"
#include "Varc_prepare_w6.h"
#include "Vdda_circle.h"
#include "arc_geometry.h"
#include "arc_prepare.h"
#include "dda_circle.h"
#include "arc_cases.h"
#include "verilated.h"
#include "verilated_clock.h"

namespace ncinterp {
namespace {

using circle_study::QuadrantArc;

using test::clock_edge;
using test::reset;

// Plays one arc on the verilated dda_circle and on CircleDda with the same random strobes;
// returns a failure naming the first clock and signal that differ.
::testing::AssertionResult dda_lockstep(Vdda_circle& m, const QuadrantArc& arc, std::mt19937_64& rng) {
  const ArcWords w = arc.words();
  const ArcGeometry g = arc_geometry(w, 16);
  CircleDda golden;
  golden.load(g, !w.dx_neg, !w.dy_neg);
  m.load_i = 1;
  m.strobe_i = rng() % 2;  // ignored at a load edge
  m.k_i = static_cast<uint8_t>(g.k);
  m.x_i = static_cast<uint16_t>(g.x0);
  m.y_i = static_cast<uint16_t>(g.y0);
  m.cnt_x_i = static_cast<uint16_t>(g.cnt_x);
  m.cnt_y_i = static_cast<uint16_t>(g.cnt_y);
  m.grow_x_i = g.grow_x;
  m.grow_y_i = g.grow_y;
  m.dir_x_i = !w.dx_neg;
  m.dir_y_i = !w.dy_neg;
  clock_edge(m);
  m.load_i = 0;
  const unsigned strobe_percent = 20 + static_cast<unsigned>(rng() % 81);
  bool step_x = false, step_y = false;
  for (uint64_t clock = 1; clock < 400000; ++clock) {
    const bool strobe = rng() % 100 < strobe_percent;
    m.strobe_i = strobe;
    m.eval();
    CircleDda::Steps expect;
    const bool was_done = golden.done();
    if (strobe && !was_done) expect = golden.iterate();
    std::ostringstream where;
    where << arc.describe() << ", clock " << clock << ": ";
    if (m.done_o != was_done) return ::testing::AssertionFailure() << where.str() << "done_o";
    if (m.carry_x_o != expect.x || m.carry_y_o != expect.y)
      return ::testing::AssertionFailure() << where.str() << "carry RTL (" << int(m.carry_x_o)
                                           << ", " << int(m.carry_y_o) << ") golden ("
                                           << expect.x << ", " << expect.y << ")";
    clock_edge(m);
    step_x = expect.x;
    step_y = expect.y;
    if (m.step_x_o != step_x || m.step_y_o != step_y || m.dir_x_o != golden.dir(0) ||
        m.dir_y_o != golden.dir(1))
      return ::testing::AssertionFailure() << where.str() << "step/dir after the edge";
    if (was_done) return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << arc.describe() << ": did not finish";
}

TEST(CircleRtlLockstep, DdaCircleEqualsGoldenEveryClock) {
  auto ctx = std::make_unique<VerilatedContext>();
  Vdda_circle m(ctx.get());
  reset(m);
  std::mt19937_64 rng(3);
  for (int t = 0; t < 300; ++t) {
    const QuadrantArc a = t < 8 ? circle_study::full_quadrant(t < 4 ? 1 : 65535, t % 4, t % 2 == 0)
                                : circle_study::random_arc(rng, t % 2 ? 65535 : 300);
    ASSERT_TRUE(dda_lockstep(m, a, rng));
  }
}

// Runs one block through a verilated arc_prepare and ArcPrepare: idle clocks, run until
// done, idle again; compares done, error, code and the iteration mark every clock. The
// magnitudes turn one place at each edge with shift_o, as the decoder's registers do (the
// radius check and the dry run read them one bit per clock), and must be back in place
// when the preparation is done.
template <typename Model>
::testing::AssertionResult prepare_lockstep(Model& m, ArcPrepare& golden, const ArcWords& w,
                                            unsigned width, std::mt19937_64& rng) {
  const auto turn = [width](auto& v) {
    v = static_cast<std::remove_reference_t<decltype(v)>>((v >> 1) | ((v & 1u) << (width - 1)));
  };
  m.dx_i = w.dx;
  m.dx_neg_i = w.dx_neg;
  m.dy_i = w.dy;
  m.dy_neg_i = w.dy_neg;
  m.i_i = w.i;
  m.i_neg_i = w.i_neg;
  m.j_i = w.j;
  m.j_neg_i = w.j_neg;
  m.ccw_i = w.ccw;
  const int idle_before = static_cast<int>(rng() % 3);
  bool done = false;
  int idle_after = 2;
  for (uint64_t clock = 0; clock < (uint64_t{1} << 24) && idle_after > 0; ++clock) {
    const bool run = clock >= uint64_t(idle_before) && !done;
    m.run_i = run;
    m.eval();
    ArcPrepare::Result expect;
    if (run)
      expect = golden.edge(w);
    else
      golden.idle();
    std::ostringstream where;
    where << "dx " << (w.dx_neg ? "-" : "") << w.dx << " dy " << (w.dy_neg ? "-" : "") << w.dy
          << " i " << (w.i_neg ? "-" : "") << w.i << " j " << (w.j_neg ? "-" : "") << w.j
          << (w.ccw ? " G03" : " G02") << ", clock " << clock << ": ";
    if (m.done_o != expect.done)
      return ::testing::AssertionFailure() << where.str() << "done_o RTL " << int(m.done_o);
    if (expect.done && (m.err_o != (expect.error != TapeError::kNone) ||
                        (m.err_o && m.err_code_o != static_cast<uint8_t>(expect.error))))
      return ::testing::AssertionFailure() << where.str() << "error RTL " << int(m.err_o) << "/"
                                           << int(m.err_code_o) << " golden "
                                           << int(expect.error);
    if (m.iterate_o != expect.iterate)
      return ::testing::AssertionFailure() << where.str() << "iterate_o RTL " << int(m.iterate_o);
    if (expect.done && (m.dx_i != w.dx || m.dy_i != w.dy || m.i_i != w.i || m.j_i != w.j))
      return ::testing::AssertionFailure() << where.str() << "the words are not in place";
    const bool shift = m.shift_o;
    if (shift && !run)
      return ::testing::AssertionFailure() << where.str() << "shift_o while not running";
    clock_edge(m);
    if (shift) {
      turn(m.dx_i);
      turn(m.dy_i);
      turn(m.i_i);
      turn(m.j_i);
    }
    if (expect.done) done = true;
    if (done) --idle_after;
  }
  if (!done) return ::testing::AssertionFailure() << "arc preparation did not finish";
  return ::testing::AssertionSuccess();
}

// Random arcs at W = 16 (radius up to max_radius, some ends off the circle, some the long
// way round) through the verilated arc_prepare and its twin.
template <typename Model>
void arc_prepare_lockstep_w16(bool serial, int64_t max_radius) {
  auto ctx = std::make_unique<VerilatedContext>();
  Model m(ctx.get());
  reset(m);
  ArcPrepare golden(16, serial);
  std::mt19937_64 rng(4);
  int good = 0;
  for (int t = 0; t < 300; ++t) {
    QuadrantArc a = circle_study::random_arc(rng, t % 2 ? max_radius : 200);
    if (t % 4 == 1) a.y1 += int64_t(rng() % 7) - 3;
    if (t % 9 == 2) a.ccw = !a.ccw;
    const ArcWords w = a.words();
    if (w.dx > 65535 || w.dy > 65535) continue;
    good += check_arc(w, 16) == TapeError::kNone;
    ASSERT_TRUE(prepare_lockstep(m, golden, w, 16, rng));
  }
  EXPECT_GT(good, 150);
}

// Random words at W = 6, where every check's verdict occurs.
template <typename Model>
void arc_prepare_lockstep_w6(bool serial) {
  auto ctx = std::make_unique<VerilatedContext>();
  Model m(ctx.get());
  reset(m);
  ArcPrepare golden(6, serial);
  std::mt19937_64 rng(6);
  int codes[16] = {0};
  for (int t = 0; t < 20000; ++t) {
    ArcWords w;
    if (t % 2) {
      w = circle_study::random_arc(rng, 63).words();
      if (w.dx > 63 || w.dy > 63) continue;
    } else {
      w.dx = rng() % 64;
      w.dy = rng() % 64;
      w.i = rng() % 64;
      w.j = rng() % 64;
      w.dx_neg = rng() % 2;
      w.dy_neg = rng() % 2;
      w.i_neg = rng() % 2;
      w.j_neg = rng() % 2;
      w.ccw = rng() % 2;
      if (t % 100 == 0) w.i = w.j = 0;
    }
    ++codes[static_cast<int>(check_arc(w, 6))];
    ASSERT_TRUE(prepare_lockstep(m, golden, w, 6, rng));
  }
  // Every verdict occurred.
  for (TapeError e : {TapeError::kNone, TapeError::kValueTooWide, TapeError::kArcCrossesQuadrant,
                      TapeError::kArcEndpointOffCircle, TapeError::kArcZeroRadius})
    EXPECT_GT(codes[static_cast<int>(e)], 20) << "code " << int(e);
}

TEST(CircleRtlLockstep, ArcPrepareEqualsGoldenEveryClockAtW16) {
  arc_prepare_lockstep_w16<Varc_prepare>(false, 65535);
}

TEST(CircleRtlLockstep, ArcPrepareEqualsGoldenEveryClockAtW6) {
  arc_prepare_lockstep_w6<Varc_prepare_w6>(false);
}

// The bit-serial dry run (BitSerial): radii up to 2^12 keep the runs short (2PN clocks).
TEST(CircleRtlLockstep, BitSerialArcPrepareEqualsGoldenEveryClockAtW16) {
  arc_prepare_lockstep_w16<Varc_prepare_serial>(true, 4095);
}

TEST(CircleRtlLockstep, BitSerialArcPrepareEqualsGoldenEveryClockAtW6) {
  arc_prepare_lockstep_w6<Varc_prepare_serial_w6>(true);
}

}  // namespace
}  // namespace ncinterp
