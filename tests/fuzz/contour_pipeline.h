// The first stage on a contour a reader accepted, as `ncinterp tape` runs it, with the
// checks a fuzz target makes: a tape within tol, read back exactly, or a clear error.
// Idea: the readers are fuzzed for what they accept as much as for what they refuse; an
// accepted contour must go through the whole pipeline (chords, cutter offset, quadrant
// arcs, BLU grid, tape text, parity, reader) or fail with a one-line reason. The options
// (method, arcs, cutter offset, tol) come from the input's hash, so each input is one
// reproducible run. The work is bounded: contours beyond kMaxExtentMm or needing more than
// kMaxChords chords (Tamm's two-sided lower bound) are skipped, not run.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/contour.h"
#include "inputs/contour_inputs.h"

namespace ncinterp::fuzz {

constexpr double kMaxExtentMm = 1000.0;
constexpr size_t kMaxSegments = 200;
constexpr double kMaxChords = 5000.0;

// Runs the first stage on `contour` with options from the input's hash; calls fail() on a
// crash-worthy outcome (tape off tol, read-back differs, an unexpected exception type).
void check_first_stage(const firststage::Contour& contour, const uint8_t* data, size_t size);

// One reader fuzz input: the text is parsed as `ncinterp tape` parses a file of this kind
// (firststage::parse_contour, range checks included, default options) named `file`; a
// refusal must be an InputError naming that file and a line >= 0, an accepted contour goes
// to check_first_stage. Returns what LLVMFuzzerTestOneInput returns (-1: input too long).
int fuzz_reader(const uint8_t* data, size_t size, const char* file, firststage::InputKind kind);

}  // namespace ncinterp::fuzz
