// The programmed path: what the tape tells the interpolator to do, block by block, in
// absolute BLU coordinates of the position counters (the tape start is (0, 0)).
// Idea: the tape is read back with the software tape reader (ncinterp::tape::parse_frames),
// so the checker's notion of a block is the tape's, not either engine's. Each block is a
// straight segment (G01) or an arc about its centre (G02/G03); the distance of a tool
// position to it is measured along the block's normal: the segment's or the circle's.
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/grid_point.h"
#include "geometry/vec2.h"
#include "tape/tape.h"

namespace ncinterp::checker {

using firststage::GridPoint;
using firststage::Vec2;

struct ProgrammedBlock {
  size_t index = 0;          // 0-based position on the tape
  tape::Block tape;          // as read: N, motion, dx, dy, i, j, feed
  GridPoint start, end;      // absolute, BLU (tape start = (0, 0))
  Vec2 centre;               // arcs: absolute centre, BLU
  bool is_arc() const { return tape::is_arc(tape.motion); }
  bool is_rapid() const { return tape::is_rapid(tape.motion); }  // G00: a traverse
  // Signed sweep of an arc from start to end (rad, > 0 counter-clockwise); a block whose
  // end equals its start is a full circle.
  double sweep() const;
  // Arc length (arcs) or chord length, BLU.
  double length() const;
  // The point of the block's path at fraction s in [0, 1] (arcs: by angle; the radius goes
  // linearly from the start radius to the end radius, which may differ by < 1 BLU).
  Vec2 point_at(double s) const;
};

// The blocks of a program laid end to end from (0, 0).
std::vector<ProgrammedBlock> lay_out(const tape::Program& program);

// Distance of q from the block's path, along the path's normal: for a line the distance to
// the segment; for an arc |(|q - c|) - r(phi)| where phi is q's angle inside the sweep and
// r(phi) the radius there, or the distance to the nearer end outside the sweep.
// *along receives the fraction of the path (0..1) nearest q.
double distance_to_block(const ProgrammedBlock& block, Vec2 q, double* along = nullptr);

}  // namespace ncinterp::checker
