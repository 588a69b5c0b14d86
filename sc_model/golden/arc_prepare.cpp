// Arc preparation in the decoder (see arc_prepare.h); the steps follow rtl/arc_prepare.sv
// decision by decision.
#include "arc_prepare.h"

namespace ncinterp {

ArcPrepare::ArcPrepare(unsigned inc_width, bool bit_serial)
    : inc_width_(inc_width), serial_(bit_serial), serial_dry_(inc_width), radius_(inc_width) {
  reset();
}

void ArcPrepare::reset() {
  running_ = false;
  geometry_edges_ = 0;
  dry_ = CircleDda{};
  serial_dry_ = SerialDda(inc_width_);
  radius_ = ArcRadiusCheck(inc_width_);
}

ArcPrepare::Result ArcPrepare::edge(const ArcWords& w) {
  Result r;
  if (!running_) {
    // With BitSerial the geometry's serial pass comes first (its first run edge, then one
    // edge per bit; the words turn and come back in place).
    if (geometry_edges_ < geometry_clocks(inc_width_, serial_)) {
      ++geometry_edges_;
      return r;
    }
    geometry_edges_ = 0;
    // Start edge: geometric errors are final at once; otherwise load the dry run and
    // the radius check. The words stay as they are until done: the geometry is kept.
    g_ = arc_geometry(w, inc_width_);
    if (g_.error != TapeError::kNone) {
      r.done = true;
      r.error = g_.error;
    }
    if (serial_)
      serial_dry_.load(g_, !w.dx_neg, !w.dy_neg);
    else
      dry_.load(g_, !w.dx_neg, !w.dy_neg);
    radius_.start();
    running_ = !r.done;
    return r;
  }
  const bool check_done = radius_.done();
  const bool check_ok = radius_.ok();
  bool dry_done, dry_iterate;
  if (serial_) {
    dry_done = serial_dry_.done();
    // It is strobed at every running edge, the last one too (its strobe_i is running_q).
    dry_iterate = serial_dry_.edge(true).iterate;
  } else {
    dry_done = dry_.done();
    dry_iterate = !dry_done;
  }
  if (check_done && (!check_ok || dry_done)) {
    r.done = true;
    r.error = check_ok ? TapeError::kNone : TapeError::kArcEndpointOffCircle;
    running_ = false;
    return r;
  }
  r.iterate = dry_iterate;
  if (!serial_ && dry_iterate) dry_.iterate();
  if (!check_done) radius_.step(g_);
  return r;
}

}  // namespace ncinterp
