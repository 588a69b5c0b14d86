// Ports and parameters of the interpolator, shared by the golden model, the verilated RTL
// wrappers, the SystemC system model and the lock-step scoreboard.
// Idea: the RTL (rtl/interp_top.sv) and GoldenInterp have exactly these inputs and outputs;
// the field names follow the RTL port names without the _i/_o suffix, so a mismatch
// report and a VCD name the same signal in both implementations. The outputs are listed
// once, in interp_outputs.def, and every list of them is expanded from it; the error codes
// (TapeError) are the tape format's, in sw/host/tape/tape_errors.def. docs/architecture.md
// explains each field.
#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>

#include "bit_length.h"
#include "feed_override.h"
#include "tape.h"
#include "tape_errors.h"

namespace ncinterp {

// The microarchitecture (interp_top's BitSerial): the same ports, blocks and pulses, two
// ways of computing them. kSerial is what the boards ship and every command's default: the
// DDA of the player and of the arc's dry run bit-serial (SerialDda, 2P clocks per
// iteration), x10 + d bit-serial, the block buffer in block RAM (a block can load only once
// the RAM's read shows it: GoldenInterp::next_readable()). kParallel: one DDA iteration per
// clock (CircleDda), the block buffer in flip-flops.
enum class Arch { kSerial, kParallel };
inline const char* arch_name(Arch arch) { return arch == Arch::kSerial ? "serial" : "parallel"; }
// "serial" or "parallel"; throws std::invalid_argument naming the choices otherwise.
Arch parse_arch(const std::string& name);

// The machine's rapid rate (G00) unless a command is told another (--rapid), mm/min.
inline constexpr double kDefaultRapidMmMin = 5000.0;

// Elaboration parameters (RTL parameters of the same name) plus the static configuration
// inputs feed_modulus_i, which depends on the clock frequency, and rapid_step_i.
struct InterpConfig {
  unsigned inc_width = 16;        // IncWidth (W)
  unsigned frac_digits = 3;       // FracDigits: BLU = 10^-frac_digits mm
  unsigned feed_width = 32;       // FeedWidth
  unsigned feed_frac_digits = 3;  // FeedFracDigits
  unsigned pos_width = 32;        // PosWidth
  unsigned seq_width = 20;        // SeqWidth
  unsigned offset_width = 32;     // OffsetWidth
  unsigned modulus_width = 48;    // ModulusWidth
  Arch arch = Arch::kSerial;      // BitSerial (1 = kSerial)
  // CircleMode: G02/G03 played; without, the lines-only interpolator (an arc's G word is
  // refused, TapeError::kNoCircleMode).
  bool circle_mode = true;
  // MiscFunctions: M00, M01, M03 and M05 played; without, each is refused
  // (TapeError::kUnsupportedCode), as the iCEstick's interpolator refuses it.
  bool misc_functions = true;
  // feed_modulus_i = 60 * clock_hz * 10^feed_frac_digits.
  uint64_t feed_modulus = 60ull * 1000000ull * 1000ull;
  // rapid_step_i: the feed step S of a rapid traverse (G00), rapid_step_for(): the line's
  // iterations come at S / M per clock, so its longer axis moves at between half and all
  // of the rapid rate (a line of 2^k iterations moves max(|dx|, |dy|) >= 2^(k-1) BLU).
  uint64_t rapid_step = rapid_step_for(kDefaultRapidMmMin, 3, 3);
  // accel_step_i: the ramp step du, by which the feed generator's rate u may change per
  // clock (accel_step_for()); 0: no ramps, every block plays at its S from its first clock.
  uint64_t accel_step = 0;

  // Same elaboration parameters (everything but feed_modulus, a port): what a verilated
  // model, built with fixed parameters, requires of a configuration.
  bool same_parameters(const InterpConfig& o) const {
    return inc_width == o.inc_width && frac_digits == o.frac_digits &&
           feed_width == o.feed_width && feed_frac_digits == o.feed_frac_digits &&
           pos_width == o.pos_width && seq_width == o.seq_width &&
           offset_width == o.offset_width && modulus_width == o.modulus_width &&
           arch == o.arch && circle_mode == o.circle_mode && misc_functions == o.misc_functions;
  }

  bool serial() const { return arch == Arch::kSerial; }
  // Clocks a ramp adds at most to a block of `iterations` beside its programmed time: the
  // triangle up and down, 2 sqrt(N M / du), and the climb to the rate's cap, M / (2 du).
  uint64_t ramp_clocks(uint64_t iterations) const {
    if (accel_step == 0) return 0;
    const double m = static_cast<double>(feed_modulus), du = static_cast<double>(accel_step);
    return static_cast<uint64_t>(2 * std::sqrt(static_cast<double>(iterations) * m / du) + m / (2 * du)) + 4;
  }
  // rapid_step as the port holds it (ModulusWidth bits).
  uint64_t rapid_step_on_port() const {
    return modulus_width >= 64 ? rapid_step : rapid_step & ((uint64_t{1} << modulus_width) - 1);
  }

  // S of a rapid traverse at rapid_mm_min: one iteration per BLU of the longer axis at
  // that rate, V * 10^frac_digits BLU/min as a feed step of 10^-feed_frac_digits units.
  static constexpr uint64_t rapid_step_for(double rapid_mm_min, unsigned frac_digits,
                                           unsigned feed_frac_digits) {
    double scale = 1;
    for (unsigned i = 0; i < frac_digits + feed_frac_digits; ++i) scale *= 10;
    return static_cast<uint64_t>(rapid_mm_min * scale + 0.5);
  }

  // du for an acceleration limit of accel_mm_s2: the rate u (iterations per clock times M)
  // bounds the fastest axis's speed, u / M BLU per clock within a factor of 2, so du / M
  // BLU per clock^2 is the limit: du = A 10^frac_digits M / f^2, rounded down (never above
  // the limit); 0 when the limit is below one step.
  static uint64_t accel_step_for(double accel_mm_s2, double clock_hz, unsigned frac_digits,
                                 uint64_t feed_modulus) {
    double blu_per_mm = 1;
    for (unsigned i = 0; i < frac_digits; ++i) blu_per_mm *= 10;
    return static_cast<uint64_t>(accel_mm_s2 * blu_per_mm * static_cast<double>(feed_modulus) /
                                 (clock_hz * clock_hz));
  }

  static uint64_t feed_modulus_for(double clock_hz, unsigned feed_frac_digits) {
    uint64_t scale = 1;
    for (unsigned i = 0; i < feed_frac_digits; ++i) scale *= 10;
    return static_cast<uint64_t>(60.0 * clock_hz + 0.5) * scale;
  }
};

// Which implementation plays the interpolator: the golden model or the verilated RTL.
enum class EngineKind { kGolden, kRtl };
inline const char* engine_name(EngineKind engine) {
  return engine == EngineKind::kGolden ? "golden" : "rtl";
}

// A straight block's feed step S, the rate of its 2^k DDA iterations (k = bit length of
// max(|dx|, |dy|)): F << k for G01, the rapid step for G00 (docs/interpolator.md 5.2). Its
// programmed duration is M 2^k / S clocks, ceil(M / F) for G01.
inline unsigned __int128 line_step(const tape::Block& b, const InterpConfig& cfg) {
  if (b.motion == tape::Motion::kRapid) return cfg.rapid_step_on_port();
  const auto magnitude = [](int64_t v) { return static_cast<uint64_t>(v < 0 ? -v : v); };
  return static_cast<unsigned __int128>(b.feed) << bit_length(magnitude(b.dx) | magnitude(b.dy));
}

// The interpolator that plays tapes of `format` with a clock of `clock_hz`: the format's
// widths, the other parameters at their defaults; the feed modulus for the clock, the rapid
// step for rapid_mm_min. With the default format, the default machine (the verilated RTL's
// parameters).
// accel_mm_s2 > 0: the feed ramp at that acceleration limit (accel_step_for()); 0: none.
InterpConfig interp_config(double clock_hz, const tape::Format& format = {},
                           double rapid_mm_min = kDefaultRapidMmMin, double accel_mm_s2 = 0);
// The ramp step du of an acceleration limit on `cfg` at clock_hz (accel_step_for());
// throws std::invalid_argument, naming the smallest limit, for one below a step.
uint64_t ramp_step(double accel_mm_s2, double clock_hz, const InterpConfig& cfg);
// The tape format an interpolator with `cfg` decodes (the inverse of interp_config).
tape::Format tape_format_of(const InterpConfig& cfg);

struct InterpInputs {
  uint8_t frame = 0;
  bool frame_valid = false;
  bool tape_end = false;
  // The operator's feed hold and cycle start (hold_i, start_i): a hold from the clock after
  // hold, until the clock after start (hold wins when both come together).
  bool hold = false;
  bool start = false;
  // The feed override (G01, G02, G03) and the rapid override (G00), feed_override_i and
  // rapid_override_i: with the ramp, a block plays at this fraction of its rate, in units of
  // 1 / kOverrideOne (feed_override.h); levels, not presses.
  uint16_t feed_override = kOverrideOne;
  uint16_t rapid_override = kOverrideOne;
  // The stops (estop_i, limit_x_i, limit_y_i): one seen at an edge while the program runs
  // stops the machine until reset, in the error state with its code.
  bool estop = false;
  bool limit_x = false;
  bool limit_y = false;
  // The optional stop switch (optional_stop_i): on, an M01 block pauses as M00 does.
  bool optional_stop = false;
};

// What each kind of output (interp_outputs.def) is in C++:
//   Value      the InterpOutputs field;
//   Signal     the SystemC signal/port type, as Verilator's SystemC model declares the port
//              (bool for one bit, uint32_t for 2..32 bits);
//   to_signal / from_signal  between the two, for a port of `width` bits;
//   from_rtl   from a port of the verilated C++ model (CData, IData, ...);
//   kOneBit    traced without a width (sc_trace of a bool).
struct PortFlag {
  using Value = bool;
  using Signal = bool;
  static constexpr bool kOneBit = true;
  static Signal to_signal(Value v, unsigned) { return v; }
  static Value from_signal(Signal s, unsigned) { return s; }
  template <class P>
  static Value from_rtl(P p) { return static_cast<bool>(p); }
};

struct PortCount {
  using Value = uint32_t;
  using Signal = uint32_t;
  static constexpr bool kOneBit = false;
  static Signal to_signal(Value v, unsigned) { return v; }
  static Value from_signal(Signal s, unsigned) { return s; }
  template <class P>
  static Value from_rtl(P p) { return static_cast<Value>(p); }
};

struct PortCode {  // an error code (TapeError)
  using Value = uint8_t;
  using Signal = uint32_t;
  static constexpr bool kOneBit = false;
  static Signal to_signal(Value v, unsigned) { return v; }
  static Value from_signal(Signal s, unsigned) { return static_cast<Value>(s); }
  template <class P>
  static Value from_rtl(P p) { return static_cast<Value>(p); }
};

struct PortPosition {  // two's complement in `width` bits, sign-extended in C++
  using Value = int64_t;
  using Signal = uint32_t;
  static constexpr bool kOneBit = false;
  static Signal to_signal(Value v, unsigned width) {
    const uint64_t mask = width >= 64 ? ~0ull : (1ull << width) - 1;
    return static_cast<Signal>(static_cast<uint64_t>(v) & mask);
  }
  static Value from_signal(Signal s, unsigned width) {
    if (width >= 64) return static_cast<Value>(s);
    const uint64_t sign = 1ull << (width - 1);
    const uint64_t value = s & ((1ull << width) - 1);
    return static_cast<Value>((value ^ sign) - sign);
  }
  // The verilated port's C type is as wide as the port (VerilatedInterp checks PosWidth),
  // so its signed twin sign-extends: the cosim's hot path needs no shifts.
  template <class P>
  static Value from_rtl(P p) { return static_cast<std::make_signed_t<P>>(p); }
};

// The outputs (interp_outputs.def), field for field the RTL's ports without "_o".
struct InterpOutputs {
#define INTERP_OUTPUT(name, kind, width) Port##kind::Value name = {};
#include "interp_outputs.def"
#undef INTERP_OUTPUT

  bool operator==(const InterpOutputs& o) const {
    return true
#define INTERP_OUTPUT(name, kind, width) &&name == o.name
#include "interp_outputs.def"
#undef INTERP_OUTPUT
        ;
  }
  bool operator!=(const InterpOutputs& o) const { return !(*this == o); }
};

// A block load as the outputs show it (docs/architecture.md): busy_o rises, or block_n_o
// changes while busy. A monitor keeps these two outputs of the previous clock, not a copy
// of them all: copying the whole struct right after an engine stored its fields one by
// one stalls on store forwarding (docs/performance.md).
struct BlockLoadWatch {
  bool busy = false;                             // of the outputs kept last
  decltype(InterpOutputs::block_n) block_n = 0;
  // A block loaded at the edge that gave o (the outputs after the ones kept).
  bool loads(const InterpOutputs& o) const { return o.busy && (!busy || o.block_n != block_n); }
  void keep(const InterpOutputs& o) {
    busy = o.busy;
    block_n = o.block_n;
  }
};

}  // namespace ncinterp
