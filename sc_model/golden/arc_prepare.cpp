// Arc preparation in the decoder (see arc_prepare.h); the steps follow rtl/arc_prepare.sv
// and rtl/arc_radius_check.sv decision by decision.
#include "arc_prepare.h"

namespace ncinterp {

namespace {

uint64_t low_mask(unsigned bits) { return bits >= 64 ? ~0ull : (1ull << bits) - 1; }

uint64_t bit(uint64_t v, unsigned b) { return (v >> b) & 1u; }

}  // namespace

ArcPrepare::ArcPrepare(unsigned inc_width, unsigned feed_width)
    : inc_width_(inc_width),
      check_steps_(2 * inc_width + 3),
      step_mask_(low_mask(feed_width + inc_width + 1)) {
  reset();
}

void ArcPrepare::reset() {
  running_ = false;
  dry_ = CircleDda{};
  step_ = 0;
  count_ = check_steps_;
  a_ = sq_ = e_ = 0;
  far_ = false;
}

ArcPrepare::Result ArcPrepare::edge(const ArcWords& w, uint64_t feed) {
  const ArcGeometry g = arc_geometry(w, inc_width_);
  Result r;
  if (!running_) {
    // Start edge: geometric errors are final at once; otherwise load the dry run and
    // the radius check.
    if (g.error != TapeError::kNone) {
      r.done = true;
      r.error = g.error;
    }
    dry_.load(g, !w.dx_neg, !w.dy_neg);
    step_ = 0;
    count_ = 0;
    a_ = sq_ = e_ = 0;
    far_ = false;
    running_ = !r.done;
    return r;
  }
  const bool check_done = count_ == check_steps_;
  const bool check_ok = !far_ && sq_ <= 4 * a_;
  if (check_done && (!check_ok || dry_.done())) {
    r.done = true;
    r.error = check_ok ? TapeError::kNone : TapeError::kArcEndpointOffCircle;
    running_ = false;
    return r;
  }
  if (!dry_.done()) {
    dry_.iterate();
    step_ = (step_ + feed) & step_mask_;
  }
  if (!check_done) check_step(g);
  return r;
}

void ArcPrepare::check_step(const ArcGeometry& g) {
  const unsigned w = inc_width_;
  if (count_ < w) {
    const unsigned b = w - 1 - count_;  // MSB first: acc = 2 acc + v * v[b]
    a_ = 2 * a_ + bit(g.x0, b) * g.x0 + bit(g.y0, b) * g.y0;
    sq_ = 2 * sq_ + bit(g.x1, b) * g.x1 + bit(g.y1, b) * g.y1;
  } else if (count_ == w) {
    const int64_t e = static_cast<int64_t>(sq_) - static_cast<int64_t>(a_) - 1;
    const uint64_t mag = static_cast<uint64_t>(e < 0 ? -e : e);
    far_ = mag >= (uint64_t{1} << (w + 2));
    e_ = mag & low_mask(w + 2);
    sq_ = 0;
  } else {
    const unsigned b = 2 * w + 2 - count_;
    sq_ = 2 * sq_ + bit(e_, b) * e_;
  }
  ++count_;
}

}  // namespace ncinterp
