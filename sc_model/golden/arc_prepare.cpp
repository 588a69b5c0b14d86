// Arc preparation in the decoder (see arc_prepare.h); the steps follow rtl/arc_prepare.sv
// and rtl/arc_radius_check.sv decision by decision.
#include "arc_prepare.h"

namespace ncinterp {

namespace {

using u128 = unsigned __int128;

u128 low_mask(unsigned bits) { return (u128{1} << bits) - 1; }

unsigned bit(u128 v, unsigned b) { return static_cast<unsigned>(v >> b) & 1u; }

constexpr uint64_t kStepClamp = uint64_t{1} << 63;

}  // namespace

ArcPrepare::ArcPrepare(unsigned inc_width)
    : inc_width_(inc_width),
      check_steps_(2 * inc_width + 3) {
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
    step_ = step_ + feed < kStepClamp ? step_ + feed : kStepClamp;  // feed < 2^63: no wrap
  }
  if (!check_done) check_step(g_);
  return r;
}

void ArcPrepare::check_step(const ArcGeometry& g) {
  const unsigned w = inc_width_;
  if (count_ < w) {
    const unsigned b = w - 1 - count_;  // MSB first: acc = 2 acc + v * v[b]
    a_ = 2 * a_ + bit(g.x0, b) * g.x0 + bit(g.y0, b) * g.y0;
    sq_ = 2 * sq_ + bit(g.x1, b) * g.x1 + bit(g.y1, b) * g.y1;
  } else if (count_ == w) {
    const u128 mag = sq_ >= a_ + 1 ? sq_ - a_ - 1 : a_ + 1 - sq_;  // |B - A - 1|
    far_ = mag >= (u128{1} << (w + 2));
    e_ = mag & low_mask(w + 2);
    sq_ = 0;
  } else {
    const unsigned b = 2 * w + 2 - count_;
    sq_ = 2 * sq_ + bit(e_, b) * e_;
  }
  ++count_;
}

}  // namespace ncinterp
