// Geometry and checks of a quadrant arc block (G02/G03): the C++ twin of rtl/arc_geometry.sv
// and the exact form of the radius check of rtl/arc_radius_check.sv.
// Idea: the circle DDA works on magnitudes relative to the centre. A block's start relative
// to the centre is S = (-I, -J), its end E = S + (X, Y). Inside one quadrant both |x| and
// |y| move monotonically, so the DDA needs only |S|, |E| per axis, whether each magnitude
// grows, the pulse counts |X|, |Y| and k = bit length of the largest magnitude (modulus
// 2^k). The rules a block must pass are docs/circle-dda.md section 2; the decoder checks
// them in the order of check_arc(), and so does anything that must accept the same tapes.
#pragma once
#include <cstdint>

#include "interp_ports.h"

namespace ncinterp {

// The words of an arc block as the decoder holds them: magnitudes and signs (a "-0" keeps
// its sign, which only sets the dir output).
struct ArcWords {
  uint32_t dx = 0, dy = 0, i = 0, j = 0;
  bool dx_neg = false, dy_neg = false, i_neg = false, j_neg = false;
  bool ccw = false;  // G03 (else G02)

  // From signed values (BLU), e.g. a tape::Block.
  static ArcWords from_signed(int64_t dx, int64_t dy, int64_t i, int64_t j, bool ccw);
};

struct ArcGeometry {
  uint64_t x0 = 0, y0 = 0;        // |S| per axis (start relative to the centre)
  uint64_t x1 = 0, y1 = 0;        // |E| per axis (may exceed the register: error 4)
  uint32_t cnt_x = 0, cnt_y = 0;  // pulses per axis: |X|, |Y|
  bool grow_x = false, grow_y = false;  // |x| (|y|) grows along the arc
  unsigned k = 0;                 // bit length of max(x0, y0, x1, y1): modulus 2^k
  // The first geometric error in the decoder's order: zero radius (12), not inside one
  // quadrant (10), end outside the register (4); kNone if none. The radius check (11)
  // is separate: arc_end_on_circle().
  TapeError error = TapeError::kNone;
};

// Geometry of an arc block; inc_width is the increment register width W.
ArcGeometry arc_geometry(const ArcWords& w, unsigned inc_width);

// True when both ends lie in one closed quadrant about the centre and each coordinate
// moves the way the arc's direction goes in that quadrant (docs/circle-dda.md 2.1).
bool arc_inside_one_quadrant(const ArcWords& w);

// True when the end is at most 1 BLU off the circle through the start (centre at the
// origin): |sqrt(x1^2 + y1^2) - sqrt(x0^2 + y0^2)| <= 1, computed exactly as
// (B - A - 1)^2 <= 4A with A = x0^2 + y0^2 >= 1, B = x1^2 + y1^2. Magnitudes < 2^31.
bool arc_end_on_circle(uint64_t x0, uint64_t y0, uint64_t x1, uint64_t y1);

// Every arc check in the decoder's order (12, 10, 4, 11); kNone for a good arc.
TapeError check_arc(const ArcWords& w, unsigned inc_width);

}  // namespace ncinterp
