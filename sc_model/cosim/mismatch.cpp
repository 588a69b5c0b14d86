// The lock-step scoreboard's mismatch report: the first differing output and its line
// (see lockstep.h). Apart from the loop so that a variant build (rtl_variant/) links it
// without this build's models.
#include <sstream>

#include "lockstep.h"

namespace ncinterp::cosim {

Mismatch first_difference(const InterpOutputs& g, const InterpOutputs& r) {
  struct Field {
    const char* name;
    int64_t (*get)(const InterpOutputs&);
  };
  static const Field fields[] = {
#define INTERP_OUTPUT(name, kind, width) \
  {#name "_o", [](const InterpOutputs& o) -> int64_t { return o.name; }},
#include "interp_outputs.def"
#undef INTERP_OUTPUT
  };
  for (const Field& f : fields) {
    if (f.get(g) != f.get(r)) {
      Mismatch m;
      m.signal = f.name;
      m.expected = f.get(g);
      m.actual = f.get(r);
      return m;
    }
  }
  return Mismatch{};  // not reached when g != r
}

std::string describe(const Mismatch& m) {
  std::ostringstream s;
  s << "cycle " << m.cycle << ", block N" << m.block << ", signal " << m.signal
    << ": expected " << m.expected << ", actual " << m.actual << " (" << m.cycles_matched
    << " cycles matched)";
  return s.str();
}

}  // namespace ncinterp::cosim
