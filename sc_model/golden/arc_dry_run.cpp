// Dry run of an arc's circle DDA, clock by clock (see arc_dry_run.h); every value is
// computed and every register written as in rtl/arc_dry_run.sv.
#include "arc_dry_run.h"

namespace ncinterp {

void ArcDryRun::start(const ArcGeometry& g) {
  acc_[0] = acc_[1] = g.k == 0 ? 0 : uint64_t{1} << (g.k - 1);  // k = 0: a zero radius
  mag_[0] = g.x0;
  mag_[1] = g.y0;
  cnt_[0] = g.cnt_x;
  cnt_[1] = g.cnt_y;
  zero_[0] = g.cnt_x == 0;
  zero_[1] = g.cnt_y == 0;
  half_ = 0;
  bit_ = 0;
  pend_ = false;
  busy_ = true;
  done_ = false;
}

bool ArcDryRun::step(const ArcGeometry& g) {
  if (!busy_) return false;
  const bool first_bit = bit_ == 0, top_bit = bit_ + 1 == g.k, below_k = bit_ < g.k;
  const int c = ((half_ >> 1) ^ half_) & 1;  // C: the axis this pass integrates
  const int u = (half_ >> 1) & 1;            // U: the previous pass's axis
  const int o = 1 - c;                       // O: C's other axis
  const auto full_add = [](bool a, bool b, bool cin, bool& cout) {
    cout = (int(a) + b + cin) >= 2;
    return a != b != cin;
  };

  // U's update: mag + 1 or + all ones (- 1), cnt + all ones (- 1), when pend.
  const bool u_grow = u ? g.grow_y : g.grow_x;
  const bool mag_add = pend_ && (first_bit || !u_grow);
  bool mag_cout, cnt_cout, acc_cout;
  const bool mag_sum = full_add(mag_[u] & 1, mag_add, !first_bit && carry_mag_, mag_cout);
  const bool cnt_sum = full_add(cnt_[u] & 1, pend_, !first_bit && carry_cnt_, cnt_cout);
  const bool zrun = (first_bit || zrun_) && !cnt_sum;  // U's updated count is 0 so far
  // C's half-step: acc_C + |O|, bit k - 1 forced on when O has no pulses left.
  const bool o_mag = o == u ? mag_sum : (mag_[o] & 1) != 0;
  const bool o_zero = o == u ? zrun : zero_[o];
  const bool c_zero = c == u ? zrun : zero_[c];
  const bool addend = o_mag || (top_bit && o_zero);
  const bool acc_sum = full_add(acc_[c] & 1, addend, !first_bit && carry_acc_, acc_cout);
  const bool step = acc_cout && !c_zero;
  const bool check = top_bit && (half_ & 1) == 0;
  const bool finished = check && zrun && o_zero;

  // Every clock: each register one place round; the written ones take the adders' bits.
  const auto rotate_in = [this](uint64_t& word, bool top) {
    word = (word >> 1) | (uint64_t{top} << (w_ - 1));
  };
  for (int a = 0; a < 2; ++a) {
    rotate_in(acc_[a], a == c ? below_k && acc_sum : (acc_[a] & 1) != 0);
    rotate_in(mag_[a], a == u ? mag_sum : (mag_[a] & 1) != 0);
    rotate_in(cnt_[a], a == u ? cnt_sum : (cnt_[a] & 1) != 0);
  }
  carry_acc_ = acc_cout;
  carry_mag_ = mag_cout;
  carry_cnt_ = cnt_cout;
  zrun_ = zrun;
  if (top_bit) step_ = step;
  if (finished) {
    busy_ = false;
    done_ = true;
  }
  if (bit_ == w_ - 1) {
    bit_ = 0;
    half_ = (half_ + 1) & 3;
    pend_ = step_;
    zero_[u] = zrun;
  } else {
    ++bit_;
  }
  return check && !finished;
}

}  // namespace ncinterp
