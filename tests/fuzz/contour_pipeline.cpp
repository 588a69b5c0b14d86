// The bounded first-stage run of the reader fuzzers (see contour_pipeline.h).
#include "contour_pipeline.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "firststage.h"
#include "fuzz_check.h"
#include "inputs/input_error.h"
#include "measure/chord_bounds.h"
#include "measure/deviation_meter.h"
#include "tape/tape.h"

namespace ncinterp::fuzz {

namespace {

using namespace ncinterp::firststage;

// Every segment sampled: finite and inside the box (the tape would be huge otherwise).
bool small_enough(const Contour& c) {
  if (c.segments.size() > kMaxSegments) return false;
  auto inside = [](Vec2 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::fabs(p.x) <= kMaxExtentMm &&
           std::fabs(p.y) <= kMaxExtentMm;
  };
  if (!inside(c.origin)) return false;
  for (const Segment& s : c.segments)
    for (int k = 0; k <= 16; ++k)
      if (!inside(s.point(k / 16.0))) return false;
  return true;
}

FirstStageOptions options_for(uint64_t h) {
  static const double tols[] = {0.02, 0.1, 0.5};
  FirstStageOptions o;
  o.method = 1 + static_cast<int>(h % 3);
  o.arcs_circle = (h >> 2) & 1;
  o.cutter_radius_mm = ((h >> 3) & 3) == 0 ? 2.0 : 0.0;
  o.side_left = (h >> 5) & 1;
  o.tol_mm = tols[(h >> 6) % 3];
  o.zones = ((h >> 8) & 3) == 0;
  return o;
}

std::string options_text(const FirstStageOptions& o) {
  return "method " + std::to_string(o.method) + (o.arcs_circle ? ", arcs circle" : "") +
         ", cutter " + std::to_string(o.cutter_radius_mm) + (o.side_left ? " left" : " right") +
         ", tol " + std::to_string(o.tol_mm) + (o.zones ? ", zones" : "");
}

bool same_block(const tape::Block& a, const tape::Block& b) {
  return a.n == b.n && a.motion == b.motion && a.dx == b.dx && a.dy == b.dy && a.i == b.i &&
         a.j == b.j && a.feed == b.feed;
}

}  // namespace

void check_first_stage(const Contour& contour, const uint8_t* data, size_t size) {
  if (!small_enough(contour)) return;
  const FirstStageOptions o = options_for(input_hash(data, size));
  if (!(two_sided_lower_bound(contour, o.tol_mm) <= kMaxChords)) return;
  const std::string opts = options_text(o);
  FirstStageResult res;
  try {
    res = run_first_stage(contour, o);
  } catch (const InputError& e) {
    if (std::string(e.what()).empty()) fail("input error without a message (" + opts + ")");
    return;
  } catch (const std::invalid_argument& e) {
    if (std::string(e.what()).empty()) fail("invalid_argument without a message (" + opts + ")");
    return;
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).empty()) fail("runtime_error without a message (" + opts + ")");
    return;
  }
  // What `ncinterp tape` writes, read back by the project's reader: exactly the blocks.
  const tape::Format format = tape_format(o);
  const tape::Program program = make_program(res, o);
  std::vector<uint8_t> frames;
  try {
    frames = tape::add_parity(tape::format_program(program, format));
  } catch (const std::invalid_argument& e) {
    return;  // a value the format cannot hold, refused before writing (a clear error)
  }
  tape::Program back;
  try {
    back = tape::parse_frames(frames, format);
  } catch (const tape::TapeFormatError& e) {
    fail("the first stage wrote a tape its reader refuses: " + tape::describe(e.info()) + " (" +
         opts + ")");
  }
  if (back.blocks.size() != program.blocks.size())
    fail("read back " + std::to_string(back.blocks.size()) + " blocks of " +
         std::to_string(program.blocks.size()) + " (" + opts + ")");
  for (size_t i = 0; i < back.blocks.size(); ++i)
    if (!same_block(back.blocks[i], program.blocks[i]))
      fail("block " + std::to_string(i + 1) + " reads back different (" + opts + ")");
  // Within tol: the chord path (before the offset) against the contour, sampled at tol/8;
  // the slack covers the sampling (the measure's polylines are chords of the samples).
  if (res.contour_moves.empty()) return;
  // Planted bug: the first chord 1 mm too long in X (must be found).
  if (injected("chord_off_contour")) res.contour_moves.front().to.x += std::lround(1.0 / o.blu_mm);
  const DeviationReport dev =
      measure_deviation(contour, res.contour_start, res.contour_moves, o.blu_mm, o.tol_mm / 8);
  if (!(dev.max_mm <= o.tol_mm * 1.01 + o.blu_mm))
    fail("tape deviates " + std::to_string(dev.max_mm) + " mm from the contour (" + opts + ")");
}

int fuzz_reader(const uint8_t* data, size_t size, const char* file, InputKind kind) {
  if (size > 16384) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Contour contour;
  try {
    contour = parse_contour(kind, text, file, InputOptions{});
  } catch (const InputError& e) {
    if (e.file() != file || e.line() < 0) fail(std::string("bad input error: ") + e.what());
    return 0;
  }
  check_first_stage(contour, data, size);
  return 0;
}

}  // namespace ncinterp::fuzz
