// Messages of the interpolator's error codes (tape_errors.def), shared by every report.
#include "tape_errors.h"

namespace ncinterp {

const char* tape_error_message(TapeError code) {
  switch (code) {
#define TAPE_ERROR(name, code, message) \
  case TapeError::k##name: return message;
#include "tape_errors.def"
#undef TAPE_ERROR
  }
  return "unknown error code";
}

}  // namespace ncinterp
