// VCD window (see vcd_window.h): bound parsing and block -> cycle resolution by a golden
// pre-pass that watches the same port events the system monitor does.
#include "vcd_window.h"

#include <stdexcept>

#include "frame_source.h"
#include "interp_top.h"

namespace ncinterp::system {

VcdBound parse_vcd_bound(const std::string& text) {
  const bool block = !text.empty() && (text[0] == 'N' || text[0] == 'n');
  const std::string digits = block ? text.substr(1) : text;
  if (digits.empty() || digits.size() > 18 ||
      digits.find_first_not_of("0123456789") != std::string::npos)
    throw std::invalid_argument("'" + text + "' is neither a cycle (1000) nor a block (N12)");
  VcdBound b;
  b.kind = block ? VcdBound::Kind::kBlock : VcdBound::Kind::kCycle;
  b.value = std::stoull(digits);
  return b;
}

namespace {

struct BlockSpan {
  uint64_t load = 0, end = 0;
  bool found = false, ended = false;
};

// Load and end edge of the first block with N = n, from a golden run.
BlockSpan find_block(uint32_t n, const std::vector<uint8_t>& frames, const InterpConfig& cfg,
                     uint64_t cycles_per_frame, uint64_t max_cycles) {
  GoldenInterp dut(cfg);
  dut.reset();
  FrameSource source(frames, cycles_per_frame);
  const InterpOutputs& o = dut.outputs();
  BlockLoadWatch last;
  last.keep(o);
  BlockSpan span;
  bool in_block = false;
  while (!o.done && !o.error && dut.cycle() < max_cycles) {
    const bool ready = o.frame_ready;
    dut.tick(source.inputs());
    source.clock(ready);
    const bool load = last.loads(o);
    if (in_block && (load || !o.busy)) {
      span.end = dut.cycle();
      span.ended = true;
      return span;
    }
    if (load && o.block_n == n) {
      span.load = dut.cycle();
      span.found = in_block = true;
    }
    last.keep(o);
  }
  return span;
}

uint64_t resolve(const VcdBound& b, bool is_end, const std::vector<uint8_t>& frames,
                 const InterpConfig& cfg, uint64_t cpf, uint64_t max_cycles) {
  if (b.kind == VcdBound::Kind::kCycle) return b.value;
  const BlockSpan span = find_block(static_cast<uint32_t>(b.value), frames, cfg, cpf, max_cycles);
  if (!span.found)
    throw std::runtime_error("VCD window: block N" + std::to_string(b.value) +
                             " never plays on this tape");
  if (is_end && !span.ended)
    throw std::runtime_error("VCD window: block N" + std::to_string(b.value) + " never ends");
  return is_end ? span.end : span.load;
}

}  // namespace

CycleWindow resolve_vcd_window(const std::optional<VcdBound>& from,
                               const std::optional<VcdBound>& to,
                               const std::vector<uint8_t>& frames, const InterpConfig& cfg,
                               uint64_t cycles_per_frame, uint64_t max_cycles) {
  CycleWindow w;
  if (from) w.from = resolve(*from, false, frames, cfg, cycles_per_frame, max_cycles);
  if (to) w.to = resolve(*to, true, frames, cfg, cycles_per_frame, max_cycles);
  if (w.from > w.to)
    throw std::runtime_error("VCD window: --vcd-from (cycle " + std::to_string(w.from) +
                             ") is after --vcd-to (cycle " + std::to_string(w.to) + ")");
  return w;
}

}  // namespace ncinterp::system
