// Arc preparation in the decoder (see arc_prepare.h); the steps follow rtl/arc_prepare.sv
// decision by decision.
#include "arc_prepare.h"

namespace ncinterp {

ArcPrepare::ArcPrepare(unsigned inc_width)
    : inc_width_(inc_width), radius_(inc_width) {
  reset();
}

void ArcPrepare::reset() {
  running_ = false;
  dry_ = CircleDda{};
  radius_ = ArcRadiusCheck(inc_width_);
}

ArcPrepare::Result ArcPrepare::edge(const ArcWords& w) {
  Result r;
  if (!running_) {
    // Start edge: geometric errors are final at once; otherwise load the dry run and
    // the radius check. The words stay as they are until done: the geometry is kept.
    g_ = arc_geometry(w, inc_width_);
    if (g_.error != TapeError::kNone) {
      r.done = true;
      r.error = g_.error;
    }
    dry_.load(g_, !w.dx_neg, !w.dy_neg);
    radius_.start();
    running_ = !r.done;
    return r;
  }
  const bool check_done = radius_.done();
  const bool check_ok = radius_.ok();
  if (check_done && (!check_ok || dry_.done())) {
    r.done = true;
    r.error = check_ok ? TapeError::kNone : TapeError::kArcEndpointOffCircle;
    running_ = false;
    return r;
  }
  if (!dry_.done()) {
    dry_.iterate();
    r.iterate = true;
  }
  if (!check_done) radius_.step(g_);
  return r;
}

}  // namespace ncinterp
