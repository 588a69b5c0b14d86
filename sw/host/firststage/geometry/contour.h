// A part contour: one chain of segments, each starting where the one before ends, read
// from any input kind (JSON, G-code, airfoil). Rapid moves (G0) are segments too, marked.
// Idea: inputs only build this chain; the chord planner, the cutter offset and the reports
// work on it without knowing where it came from.
#pragma once
#include <string>
#include <vector>

#include "geometry/segment.h"

namespace ncinterp::firststage {

// Joints whose tangents turn by more than this are corners: always chord vertices.
// (A smaller turn is taken as a smooth joint that a chord may cross; see docs/inputs.md.)
constexpr double kSmoothJointAngle = 1e-3;  // rad

// One cutting pass of a G-code program: its depth and the input elements taped in it (the
// traverse to each run of cuts, the cuts, and after the last pass the traverse to where the
// program ends). Contours from other inputs have one pass without a depth.
struct CutPass {
  double depth_mm;       // Z of the pass; NaN: the program has no Z
  int first_element = 0;  // elements [first_element, end_element) in Contour::element_names
  int end_element = 0;
};

struct Contour {
  std::string file;                 // input file, for messages
  Vec2 origin;                      // position before the first segment (mm)
  std::vector<Segment> segments;    // mm
  // One name per input element (source_index), e.g. "line 12 (G2)", "segment 3 (table)".
  std::vector<std::string> element_names;
  // What the reader ignored or doubts, one line each ("FILE: warning: ..."); printed by
  // the commands on stderr.
  std::vector<std::string> warnings;
  // G-code with several cutting depths: one pass per depth, shallowest first, in the
  // order of the segments. Empty: one pass of every element.
  std::vector<CutPass> passes;
  // Airfoil inputs: the trailing-edge points are corners, the rest of the spline is smooth.

  Vec2 end() const { return segments.empty() ? origin : segments.back().end(); }
  bool closed() const;
};

// A contour built in code (tests, benchmarks): segment i is input element i, named
// "segment i+1".
Contour contour_from_segments(const std::string& file, Vec2 origin, std::vector<Segment> segments);

// Turn angle (rad, >= 0) of the tangent from the end of a to the start of b.
double joint_turn(const Segment& a, const Segment& b);
// True when a chord may cross the joint between a and b (no rapid, tangents agree).
bool smooth_joint(const Segment& a, const Segment& b);

}  // namespace ncinterp::firststage
