// What the check's SVG shows, as plain series in mm, independent of how it is drawn.
// Idea: a person wants to see (1) the whole part: contour, programmed chords and arcs, the
// pulse path; (2) the worst point up close, where the staircase of single pulses, the chord
// and the contour are all visible; (3) the error along the path against the tolerance band.
// A part is 10^5 BLU across and has 10^5..10^6 pulses, so each view keeps only what its scale
// can show: the overview draws the programmed path (the staircase is within a BLU of it), the
// zoom draws every pulse inside its window, the error curve keeps the max and min of each of
// about a thousand bins along the path (so no peak is lost); (4) the feed profile, each
// axis's speed against time, from the pulses counted in bins of equal time (a pulse is one
// BLU), where the ramps, the holds and the corners show.
#pragma once
#include <string>
#include <vector>

#include "check_session.h"

namespace ncinterp::checker {

struct PlotPoint {
  double x = 0.0, y = 0.0;  // mm
};
using Polyline = std::vector<PlotPoint>;

struct PlotWindow {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // mm
  bool contains(PlotPoint p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
};

struct ErrorBin {
  double s_mm = 0.0;                     // path length at the bin's start
  double total_max = -1.0, total_min = -1.0;  // mm; -1: no total error measured in the bin
  double path_max = 0.0;                 // interpolator error, mm
};

struct SpeedBin {
  double t_s = 0.0;                      // the bin's start, seconds of machine time
  double x_mm_min = 0.0, y_mm_min = 0.0; // each axis's speed over the bin (pulses x BLU / time)
};

struct CheckPlotData {
  std::vector<Polyline> contour;       // cutting segments, densely sampled
  std::vector<Polyline> rapids;        // input G0 moves
  Polyline programmed;                 // block ends (and arc samples), tape start first
  std::vector<PlotPoint> vertices;     // block ends
  PlotWindow overview;                 // bounds of everything, with a margin
  // The worst point: where the total error is largest (else the interpolator error).
  bool has_worst = false;
  PlotPoint worst, worst_foot;         // tool position and its nearest contour point
  double worst_error_mm = 0.0;
  uint32_t worst_block = 0;
  uint64_t worst_cycle = 0;
  PlotWindow zoom;                     // square window around the worst point
  std::vector<Polyline> zoom_contour;  // contour pieces inside the zoom, dense
  std::vector<Polyline> zoom_programmed;  // programmed path clipped to the zoom (runs)
  std::vector<Polyline> zoom_pulses;   // every pulse position in the zoom, in order (runs)
  std::vector<ErrorBin> error_bins;    // along the path
  std::vector<SpeedBin> speed_bins;    // over time, from clock 0 to the last pulse
  double path_length_mm = 0.0;
  double tol_mm = 0.0;
  bool total_measured = false;
  bool cutter = false;                 // the zoom's contour is the cutter-centre path
};

// Needs the outcome's pulses (CheckSetup::keep_pulses). clock_hz turns clocks into time.
CheckPlotData check_plot_data(const CheckOutcome& outcome, double tol_mm, double clock_hz,
                              size_t bins = 1000, size_t speed_bins = 500);

}  // namespace ncinterp::checker
