// Tape writer: Program -> ISO 6983 word-address text, one LF-terminated block per line.
// Idea: the writer only produces tapes the reader (and so the interpolator) accepts: every
// value is checked against the Format's register widths before anything is written, and
// numbers always carry exactly the required fraction digits. A G00 (traverse) block is
// written without F: it plays at the machine's rapid rate.
#include <sstream>
#include <stdexcept>

#include "arc_rules.h"
#include "tape.h"

namespace ncinterp::tape {

namespace {

uint64_t max_for_width(unsigned bits) { return bits >= 64 ? ~0ull : (1ull << bits) - 1; }

uint64_t magnitude(int64_t v) {
  return v < 0 ? -static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
}

// A magnitude in units of 10^-frac_digits as "int.frac" with exactly frac_digits digits
// after the point ("12." when frac_digits is 0).
std::string fixed_point(uint64_t value, unsigned frac_digits) {
  std::string digits = std::to_string(value);
  if (digits.size() <= frac_digits) digits.insert(0, frac_digits + 1 - digits.size(), '0');
  digits.insert(digits.size() - frac_digits, ".");
  return digits;
}

std::string signed_fixed_point(int64_t value, unsigned frac_digits) {
  const std::string digits = fixed_point(magnitude(value), frac_digits);
  return value < 0 ? "-" + digits : digits;
}

void check_sequence(const Block& b, const Format& f, const std::string& where) {
  if (b.n > max_for_width(f.seq_width))
    throw std::invalid_argument(where + "N exceeds the sequence register");
}

// The block's M word (tape_codes.def), or null.
const char* m_word(const Block& b) {
  return b.stop ? "M00" : b.optional_stop ? "M01" : b.tool_on ? "M03" : b.tool_off ? "M05" : nullptr;
}

void check_block(const Block& b, const Format& f) {
  const auto where = "block N" + std::to_string(b.n) + ": ";
  if (b.stop + b.optional_stop + b.tool_on + b.tool_off > 1)
    throw std::invalid_argument(where + "more than one M word (one M word per block)");
  if (b.still && (!m_word(b) || b.dx != 0 || b.dy != 0 || b.i != 0 || b.j != 0 ||
                  !is_rapid(b.motion) || b.feed != 0))
    throw std::invalid_argument(where + "a still block has an M word and nothing else");
  const uint64_t inc_max = max_for_width(f.inc_width);
  auto check_inc = [&](int64_t v, const char* word) {
    if (magnitude(v) > inc_max)
      throw std::invalid_argument(where + word + " " + std::to_string(v) +
                                  " BLU exceeds the increment register (2^" +
                                  std::to_string(f.inc_width) + " - 1)");
  };
  check_inc(b.dx, "X");
  check_inc(b.dy, "Y");
  check_inc(b.i, "I");
  check_inc(b.j, "J");
  if (!is_arc(b.motion) && (b.i != 0 || b.j != 0))
    throw std::invalid_argument(where + "a " + motion_word(b.motion) + " block has I/J");
  if (is_arc(b.motion)) {
    const ArcRuleBroken broken = broken_arc_rule(b, inc_max);
    if (broken.code != TapeError::kNone) throw std::invalid_argument(where + broken.message);
  }
  if (is_rapid(b.motion)) {
    // The reader gives a G00 block feed 0 whatever F the tape has: written so, read so.
    if (b.feed != 0) throw std::invalid_argument(where + "a G00 block has no F (it plays at the rapid rate)");
    return check_sequence(b, f, where);
  }
  if (b.feed == 0) throw std::invalid_argument(where + "feed F is 0");
  if (b.feed > max_for_width(f.feed_width))
    throw std::invalid_argument(where + "feed exceeds the F register");
  check_sequence(b, f, where);
}

}  // namespace

const char* motion_word(Motion m) {
  switch (m) {
#define TAPE_MOTION(name, code, word) \
  case Motion::k##name: return word;
#include "tape_motions.def"
#undef TAPE_MOTION
  }
  return "G??";
}

std::string format_program(const Program& program, const Format& format) {
  std::ostringstream out;
  out << "%\nG17 G21 G91 G93\n";
  for (const Block& b : program.blocks) {
    check_block(b, format);
    out << 'N' << b.n;
    if (!b.still) {
      out << ' ' << motion_word(b.motion) << " X" << signed_fixed_point(b.dx, format.frac_digits)
          << " Y" << signed_fixed_point(b.dy, format.frac_digits);
      if (is_arc(b.motion))
        out << " I" << signed_fixed_point(b.i, format.frac_digits)
            << " J" << signed_fixed_point(b.j, format.frac_digits);
      if (!is_rapid(b.motion)) out << " F" << fixed_point(b.feed, format.feed_frac_digits);
    }
    if (const char* m = m_word(b)) out << ' ' << m;
    out << '\n';
  }
  out << (program.end_m30 ? "M30" : "M02") << "\n%\n";
  return out.str();
}

}  // namespace ncinterp::tape
