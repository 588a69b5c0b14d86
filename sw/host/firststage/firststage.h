// The first stage, from a contour to tape blocks: spans -> chords within delta on the BLU
// grid (or quadrant arcs) -> cutter-centre offset -> register-width split -> feed.
// Idea: every position is an integer grid point from the start; a move is the difference
// of two grid points, so the chain closes exactly on the programmed (rounded) end points.
#pragma once
#include <string>
#include <vector>

#include "chords/chord_planner.h"
#include "geometry/contour.h"
#include "tape/tape.h"

namespace ncinterp::firststage {

// Width of the interpolator's position counters (PosWidth, docs/architecture.md): every
// point of a contour must be within +-(2^31 - 1) BLU.
constexpr int kPositionBits = 32;

struct FirstStageOptions {
  int method = 3;              // 1 trial, 2 one-sided, 3 two-sided
  double tol_mm = 0.01;        // delta: how far the pulse path may be from the contour
  double blu_mm = 0.001;       // grid; must be 10^-k mm (k = tape fraction digits)
  unsigned width = 16;         // increment register W: |dx|,|dy|,|i|,|j| <= 2^W - 1
  unsigned feed_width = 32;    // F register: F <= 2^feed_width - 1 (tape::Format::feed_width)
  bool arcs_circle = false;    // arcs as quadrant arc blocks instead of chords
  double cutter_radius_mm = 0.0;  // 0: no offset (tape = contour)
  bool side_left = true;       // cutter on the left of the direction of travel (G41)
  double feed_mm_min = 1000.0;
  bool zones = false;          // end chords at every joint (reference point), as the paper
  double budget_blu = 1.0;     // interpolator's own error, reserved from delta
  // The tool output on for the cuts only (a laser, torch or pen): M03 with the first cut
  // of every run of cuts, M05 with its last (make_program()).
  bool tool = false;
  // With `tool`: seconds the tool is on at rest before each run of cuts (a torch's or a
  // laser's pierce delay): a block of M03 and a dwell, a G01 without X and Y that lasts
  // 1/F (make_program()); 0: none.
  double pierce_delay_s = 0.0;
  // The machine's acceleration limit, mm/s^2 (0: none): an arc's feed is lowered to
  // sqrt(A R), so that its centripetal acceleration v^2 / R stays within it (the feed ramp
  // limits the rate along the path only; make_program(), arc_feed_mm_min()).
  double accel_mm_s2 = 0.0;
};

enum class MoveKind { kLine, kArcCw, kArcCcw };

struct Move {
  MoveKind kind = MoveKind::kLine;
  GridPoint to;       // end, BLU (absolute)
  GridPoint centre;   // arcs: centre, BLU (absolute)
  int element = -1;   // input element the move belongs to (-1: added by the offset)
  bool chord = false; // a chord of a curve (not a programmed line, arc or rapid)
  bool rapid = false; // a G0 move: not cut, not offset
};

struct FirstStageResult {
  GridPoint start;               // tape start, BLU (absolute)
  std::vector<Move> moves;
  // The contour's own path (before any cutter offset): chords and arcs from contour_start
  // (the contour's origin on the grid; = start without an offset).
  GridPoint contour_start;
  std::vector<Move> contour_moves;
  std::vector<int> chords_per_element;
  PlannerStats planner;
  double chord_delta_mm = 0.0;   // the deviation the chords were held to (tol - budget ...)
  int frac_digits = 3;
  // "FILE: warning: ..." lines: the contour's path or the cutter path crosses itself
  // (measure/self_intersection.h). The commands print them on stderr.
  std::vector<std::string> warnings;
};

// Checks the options (throws std::invalid_argument with a one-line reason).
void validate_options(const FirstStageOptions& options);
FirstStageResult run_first_stage(const Contour& contour, const FirstStageOptions& options);
// Moves -> tape program (G01/G02/G03 blocks with inverse-time F, traverses as G00 blocks
// without F, N from 1).
tape::Program make_program(const FirstStageResult& result, const FirstStageOptions& options);
tape::Format tape_format(const FirstStageOptions& options);
// Inverse-time feed in 10^-FeedFracDigits 1/min for a move of `length_mm` at
// `feed_mm_min`: rounded down (the block is never faster than the feed), at least 1. A
// block too short for its feed would need F beyond the F register: it gets the largest F
// (1/F = 60 s / ((2^FeedWidth - 1) 10^-FeedFracDigits), 14 us at the defaults), so it is
// a little slower than programmed, never faster; so short a block saturates anyway.
uint64_t inverse_time_feed(double length_mm, double feed_mm_min, const tape::Format& format);
// The feed of an arc of radius `radius_mm`: feed_mm_min, at most 60 sqrt(A R) mm/min with an
// acceleration limit A (options.accel_mm_s2 > 0).
double arc_feed_mm_min(double radius_mm, const FirstStageOptions& options);
// Length of a move in mm (arc length for arcs).
double move_length_mm(GridPoint from, const Move& move, double blu_mm);

}  // namespace ncinterp::firststage
