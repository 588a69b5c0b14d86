// The interpolator's error codes and their messages, from the one list tape_errors.def.
// Idea: the codes are the tape format's contract, so they live in the lowest library (the
// tape library); the golden model, the verilated RTL's reports and the software reader all
// use this enum, and rtl/0_interp_pkg.sv is generated from the same .def.
#pragma once
#include <cstdint>

namespace ncinterp {

enum class TapeError : uint8_t {
#define TAPE_ERROR(name, code, message) k##name = code,
#include "tape_errors.def"
#undef TAPE_ERROR
};

// Bits of an error code (the width of the interpolator's error_code_o): enough for the
// largest code in tape_errors.def.
constexpr unsigned kTapeErrorBits = [] {
  unsigned largest = 0, bits = 1;
#define TAPE_ERROR(name, code, message) largest = (code) > largest ? (code) : largest;
#include "tape_errors.def"
#undef TAPE_ERROR
  while ((largest >> bits) != 0) ++bits;
  return bits;
}();

// The short message of a code ("parity error", ...); "unknown error code" for any other.
const char* tape_error_message(TapeError code);

// A code of the machine's own stops (E-stop, a limit switch), not of a tape fault.
constexpr bool is_stop_error(unsigned code) {
  return code == static_cast<unsigned>(TapeError::kEmergencyStop) ||
         code == static_cast<unsigned>(TapeError::kLimitX) || code == static_cast<unsigned>(TapeError::kLimitY);
}

}  // namespace ncinterp
