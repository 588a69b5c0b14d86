// G-code as CAM posts write it (examples/contours/cam/, in the style of Fusion 360, FreeCAD,
// Estlcam, pcb-gcode, a plasma and a laser post, LinuxCNC): the machine words are ignored
// and listed in one warning; each cutting depth is a pass of its own, G0 moves, ramps and
// helices are traverses (counted in a warning); what cannot be read is refused with the
// reason and its line (examples/contours/cam/refused/).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "inputs/contour_inputs.h"
#include "test_helpers.h"

namespace ncinterp::test {
namespace {

const std::string kCam = std::string(NCINTERP_EXAMPLES_DIR) + "/cam/";

// The cut of every CAM example: the 40 x 30 mm plate with R5 corners, counter-clockwise
// from (5, 0): four lines and four quarter arcs.
void expect_plate_cut(const firststage::Contour& c) {
  std::vector<const firststage::Segment*> cut;
  for (const auto& s : c.segments)
    if (!s.rapid) cut.push_back(&s);
  ASSERT_EQ(cut.size(), 8u);
  double sweep = 0;
  for (const auto* s : cut) {
    if (s->is_arc()) {
      EXPECT_NEAR(s->radius(), 5.0, 1e-9);
      sweep += s->sweep();
    }
  }
  EXPECT_NEAR(sweep, 2 * M_PI, 1e-9);  // closed, counter-clockwise
  EXPECT_NEAR(cut.front()->start().x, 5.0, 1e-9);
  EXPECT_NEAR(cut.back()->end().x, 5.0, 1e-9);
  EXPECT_NEAR(cut.back()->end().y, 0.0, 1e-9);
}

size_t cuts_of(const firststage::Contour& c) {
  size_t cuts = 0;
  for (const auto& s : c.segments) cuts += !s.rapid;
  return cuts;
}

// The cut segments of pass p.
std::vector<const firststage::Segment*> pass_cuts(const firststage::Contour& c, size_t p) {
  std::vector<const firststage::Segment*> out;
  for (const auto& s : c.segments)
    if (!s.rapid && s.source_index >= c.passes.at(p).first_element && s.source_index < c.passes.at(p).end_element)
      out.push_back(&s);
  return out;
}

// The line of the first occurrence of `text` in the file (1-based).
int line_of(const std::string& path, const std::string& text) {
  std::ifstream in(path);
  std::string l;
  for (int n = 1; std::getline(in, l); ++n)
    if (l.find(text) != std::string::npos) return n;
  return -1;
}

std::string refusal(const std::string& path, firststage::InputOptions io = {}) {
  try {
    firststage::read_contour(path, io);
  } catch (const firststage::InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(CamGcode, Fusion360PostTwoDepthPassesAreTwoPasses) {
  const firststage::Contour c = firststage::read_contour(kCam + "fusion360_profile.nc", {});
  ASSERT_EQ(c.passes.size(), 2u);
  EXPECT_EQ(c.passes[0].depth_mm, -1.0);  // shallowest first
  EXPECT_EQ(c.passes[1].depth_mm, -2.0);
  EXPECT_EQ(cuts_of(c), 16u);
  for (size_t p = 0; p < 2; ++p) EXPECT_EQ(pass_cuts(c, p).size(), 8u);
  ASSERT_EQ(c.warnings.size(), 1u);
  const std::string& w = c.warnings[0];
  for (const char* word : {"O (line 2)", "G28 (line 7)", "T (line 11)", "M6 (line 11)", "S (line 12)",
                           "M3 (line 12)", "G54 (line 13)", "M8 (line 14)", "G43", "H", "M9", "M5"})
    EXPECT_NE(w.find(word), std::string::npos) << word << " not in: " << w;
}

TEST(CamGcode, FreecadPostWithZAndKOnEveryMove) {
  const firststage::Contour c = firststage::read_contour(kCam + "freecad_profile.ngc", {});
  expect_plate_cut(c);
  ASSERT_EQ(c.warnings.size(), 1u);
  for (const char* word : {"G54", "G49", "G80", "M5", "M6", "T", "G43", "H", "M3", "S", "K"})
    EXPECT_NE(c.warnings[0].find(word), std::string::npos) << word << " not in: " << c.warnings[0];
}

TEST(CamGcode, EstlcamPostRampIsATraverseDwellIgnored) {
  const firststage::Contour c = firststage::read_contour(kCam + "estlcam_profile.nc", {});
  // The ramp from Z0 down to Z-1 is a traverse; the way back along it is at depth.
  EXPECT_EQ(cuts_of(c), 9u);  // the way back to the start of the ramp, then the plate
  EXPECT_NE(c.warnings.at(0).find("G4"), std::string::npos) << c.warnings[0];
  ASSERT_EQ(c.warnings.size(), 2u);
  EXPECT_NE(c.warnings[1].find("1 feed move (G1/G2/G3) taped as traverses (G00)"), std::string::npos)
      << c.warnings[1];
  EXPECT_NE(c.warnings[1].find("1 ramps or helices"), std::string::npos) << c.warnings[1];
}

TEST(CamGcode, CutZKeepsOnePassAndCountsTheOthersAsTraverses) {
  firststage::InputOptions io;
  io.cut_z_mm = -1.0;
  const firststage::Contour c = firststage::read_contour(kCam + "fusion360_profile.nc", io);
  ASSERT_EQ(c.passes.size(), 1u);
  EXPECT_EQ(c.passes[0].depth_mm, -1.0);
  expect_plate_cut(c);
  ASSERT_EQ(c.warnings.size(), 2u);
  EXPECT_NE(c.warnings[1].find("8 feed moves"), std::string::npos) << c.warnings[1];
  EXPECT_NE(c.warnings[1].find("8 at other depths than --cut-z -1 (first on line " +
                              std::to_string(line_of(kCam + "fusion360_profile.nc", "N120 ")) + ")"),
            std::string::npos) << c.warnings[1];
  io.cut_z_mm = -5.0;
  const std::string e = refusal(kCam + "fusion360_profile.nc", io);
  EXPECT_NE(e.find(":0: no XY feed move at the cutting depth Z-5 mm (--cut-z): the program cuts at Z-1, Z-2 mm"),
            std::string::npos) << e;
}

// The minimal case of the issue: a line cut at Z-1 and Z-2 in pieces (tabs). Each depth is
// a pass; a pass's pieces are joined by traverses, never by a cut.
TEST(CamGcode, DepthsWithTabsArePassesOfTheirPieces) {
  const firststage::Contour c = firststage::read_contour(kCam + "depth_passes_minimal.nc", {});
  ASSERT_EQ(c.passes.size(), 2u);
  const auto p1 = pass_cuts(c, 0), p2 = pass_cuts(c, 1);
  ASSERT_EQ(p1.size(), 2u);  // X0 -> X60 and X55 -> X35 at Z-1
  ASSERT_EQ(p2.size(), 2u);  // X60 -> X55 and X35 -> X0 at Z-2
  EXPECT_EQ(p1[0]->start().x, 0.0);
  EXPECT_EQ(p1[0]->end().x, 60.0);
  EXPECT_EQ(p1[1]->start().x, 55.0);
  EXPECT_EQ(p2[0]->start().x, 60.0);
  EXPECT_EQ(p2[1]->end().x, 0.0);
  // The chain: cut, traverse 60 -> 55, cut, traverse 35 -> 60, cut, traverse 55 -> 35, cut.
  std::vector<bool> rapid;
  for (const auto& s : c.segments) rapid.push_back(s.rapid);
  EXPECT_EQ(rapid, (std::vector<bool>{false, true, false, true, false, true, false}));
  EXPECT_TRUE(c.warnings.empty());
}

TEST(CamGcode, Fusion360ThreePassesTabsAndAHelicalEntry) {
  const std::string file = kCam + "fusion360_passes_tabs.nc";
  const firststage::Contour c = firststage::read_contour(file, {});
  ASSERT_EQ(c.passes.size(), 3u);
  EXPECT_EQ(c.passes[2].depth_mm, -3.0);
  // Z-1: the lead-in line, the lead-in arc, the plate (8), the lead-out arc. Z-2: lead-in
  // arc, plate, lead-out, and the tab tops of the last pass (2). Z-3: the plate cut in four
  // pieces by the tabs, lead-in and lead-out.
  EXPECT_EQ(pass_cuts(c, 0).size(), 11u);
  EXPECT_EQ(pass_cuts(c, 1).size(), 12u);
  EXPECT_EQ(pass_cuts(c, 2).size(), 12u);
  // Two helix turns, the ramp into the last pass and the two ramps of the second tab.
  ASSERT_EQ(c.warnings.size(), 2u);
  EXPECT_NE(c.warnings[1].find("5 feed moves (G1/G2/G3) taped as traverses (G00), not cut: 5 ramps or helices"),
            std::string::npos) << c.warnings[1];
  EXPECT_NE(c.warnings[1].find("first on line " + std::to_string(line_of(file, "N70 "))), std::string::npos)
      << c.warnings[1];
}

TEST(CamGcode, FreecadGrblHelixIsAnEntryAndTheDiscTwoPasses) {
  const firststage::Contour c = firststage::read_contour(kCam + "freecad_grbl_disc.gcode", {});
  ASSERT_EQ(c.passes.size(), 2u);
  // Z-1: the disc (two half circles); Z-2: the bore's two bottom half circles and the disc.
  EXPECT_EQ(pass_cuts(c, 0).size(), 2u);
  EXPECT_EQ(pass_cuts(c, 1).size(), 4u);
  EXPECT_NE(c.warnings.back().find("4 ramps or helices"), std::string::npos) << c.warnings.back();
}

TEST(CamGcode, EstlcamHelicalHolesAndARampedStrip) {
  const firststage::Contour c = firststage::read_contour(kCam + "estlcam_bolt_holes.nc", {});
  ASSERT_EQ(c.passes.size(), 2u);
  EXPECT_EQ(c.passes[0].depth_mm, -1.5);
  // Z-1.5: a circle per hole, the way back along the ramp and the strip (8); the same at Z-3.
  EXPECT_EQ(pass_cuts(c, 0).size(), 11u);
  EXPECT_EQ(pass_cuts(c, 1).size(), 11u);
  EXPECT_NE(c.warnings.back().find("10 ramps or helices"), std::string::npos) << c.warnings.back();
}

TEST(CamGcode, PcbGcodeTapIsGcodeInInchOnePass) {
  const firststage::Contour c = firststage::read_contour(kCam + "pcb_gcode_etch.tap", {});
  ASSERT_EQ(c.passes.size(), 1u);
  EXPECT_NEAR(c.passes[0].depth_mm, -0.0508, 1e-12);
  EXPECT_EQ(cuts_of(c), 10u);  // two isolation passes: a stadium (4) and a circle each
  for (const auto& s : c.segments)
    if (s.is_arc()) EXPECT_TRUE(std::fabs(s.radius() - 1.524) < 1e-9 || std::fabs(s.radius() - 1.905) < 1e-9)
        << s.radius();
}

TEST(CamGcode, PlasmaTapAtCutHeightAndLaserWithoutZ) {
  const firststage::Contour plasma = firststage::read_contour(kCam + "plasma_mach3_flange.tap", {});
  ASSERT_EQ(plasma.passes.size(), 1u);
  EXPECT_EQ(plasma.passes[0].depth_mm, 1.5);  // the torch's cut height: a depth like any
  EXPECT_EQ(cuts_of(plasma), 10u);            // lead-in and circle, five times
  const firststage::Contour laser = firststage::read_contour(kCam + "laser_lightburn.gcode", {});
  ASSERT_EQ(laser.passes.size(), 1u);
  EXPECT_TRUE(std::isnan(laser.passes[0].depth_mm));
  EXPECT_EQ(cuts_of(laser), 12u);  // the plate outline (8) and the window (4)
  EXPECT_NE(laser.warnings.at(0).find("S (line"), std::string::npos) << laser.warnings[0];
}

TEST(CamGcode, RArcsRoundedByThePostAreReadAndWordsAfterTheEndWarned) {
  const std::string file = kCam + "linuxcnc_inch_r_arcs.ngc";
  const firststage::Contour c = firststage::read_contour(file, {});
  EXPECT_EQ(cuts_of(c), 11u);
  const std::string& w = c.warnings.back();
  EXPECT_NE(w.find("2 lines after the end of the program (M2/M30 on line " +
                   std::to_string(line_of(file, "N210 M2")) + ") ignored, as LinuxCNC does"),
            std::string::npos) << w;
}

TEST(CamGcode, RArcToleranceIsTheArcEndTolerance) {
  // The arc: R1.508 to an end 3.0169 mm away, 0.00045 mm short of the half chord.
  const firststage::Contour c =
      firststage::parse_gcode("G21 G90\nG1 X0 Y0 F100\nG2 X3.0169 Y0 R1.508\nM2\n", "r.nc");
  ASSERT_EQ(c.segments.size(), 1u);
  EXPECT_NEAR(c.segments[0].radius(), 1.50845, 1e-12);  // the half circle through both ends
  EXPECT_NEAR(std::fabs(c.segments[0].sweep()), M_PI, 1e-12);
  try {
    firststage::parse_gcode("G21 G90\nG1 X0 Y0 F100\nG2 X3.0169 Y0 R1.5\nM2\n", "r.nc");
    ADD_FAILURE() << "an R 0.00845 mm short was accepted";
  } catch (const firststage::InputError& e) {
    EXPECT_STREQ(e.what(), "r.nc:3: arc radius R1.5 is 0.00845 mm shorter than half the distance to the end "
                           "point (1.508 mm; tolerance 0.002 mm)");
  }
}

TEST(CamGcode, RefusalsNameTheLineAndTheReason) {
  const std::string dir = kCam + "refused/";
  struct Case {
    std::string file, at, says;
  };
  const Case cases[] = {
      {"fusion360_vertical_leadin.nc", "N65 G18", "G18: only the XY plane (G17) is supported"},
      {"fusion360_vertical_leadin.nc", "N65 G18", "'Vertical lead-in radius' and 'Vertical lead-out radius' 0"},
      {"linuxcnc_subroutine.ngc", "o100 sub", "O-word 'o100 sub' (a subroutine) is not supported"},
      {"plasmac_parameters.ngc", "F#<", "takes a parameter: parameters and expressions are not supported"},
      {"router_vfd_header.nc", "% vfd", "'%' line with text ('% vfd enable')"},
  };
  for (const Case& k : cases) {
    const std::string e = refusal(dir + k.file);
    const std::string where = dir + k.file + ":" + std::to_string(line_of(dir + k.file, k.at)) + ": ";
    EXPECT_EQ(e.rfind(where, 0), 0u) << e;
    EXPECT_NE(e.find(k.says), std::string::npos) << e;
  }
}

TEST(CamGcode, ControlFlowParametersAndExpressionsAreRefusedWithTheReason) {
  const auto msg = [](const std::string& text) {
    try {
      firststage::parse_gcode(text, "t.nc");
    } catch (const firststage::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(msg("G1 X1 F100\no101 if [#1 GT 0]\n").find("t.nc:2: O-word 'o101 if' (a condition)"), std::string::npos);
  EXPECT_NE(msg("o102 while [1]\n").find("(a loop)"), std::string::npos);
  EXPECT_NE(msg("o<slot> call\n").find("(a named subroutine)"), std::string::npos);
  EXPECT_NE(msg("#1 = 5\n").find("t.nc:1: parameter '#1 = 5'"), std::string::npos);
  EXPECT_NE(msg("G1 X[1+2] F100\n").find("takes an expression"), std::string::npos);
  EXPECT_NE(msg("G1 X1 F100\nM98 P1000\n").find("t.nc:2: unsupported code M98 (subprogram call)"), std::string::npos);
  EXPECT_NE(msg("G83 X1 Y1 Z-3 R1 Q1\n").find("a canned cycle"), std::string::npos);
  // A program number and a '%' line with only a comment are fine.
  EXPECT_EQ(msg("% (start)\nO1234\nG1 X1 F100\nM2\n"), "accepted");
}

TEST(CamGcode, TapIsGcodeAndUnknownExtensionsListIt) {
  EXPECT_EQ(firststage::input_kind_of("part.TAP"), firststage::InputKind::kGcode);
  try {
    firststage::input_kind_of("part.cnc");
    ADD_FAILURE();
  } catch (const firststage::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(".nc/.ngc/.gcode/.tap"), std::string::npos) << e.what();
  }
}

TEST(CamGcode, WithoutZEveryMoveIsTheContourAndNothingIsListed) {
  const firststage::Contour c = firststage::parse_gcode("G21 G90\nG1 X10 Y0 F100\nG1 X10 Y10\nM2\n", "t.nc");
  ASSERT_EQ(c.segments.size(), 2u);
  EXPECT_FALSE(c.segments[0].rapid);
  EXPECT_TRUE(c.warnings.empty());
}

TEST(CamGcode, PWithoutDwellAndUnknownCodesAreStillRefused) {
  EXPECT_THROW(firststage::parse_gcode("G1 X1 Y1 P2\n", "t.nc"), firststage::InputError);
  EXPECT_THROW(firststage::parse_gcode("G81 X1 Y1 Z-1 R1\n", "t.nc"), firststage::InputError);
  EXPECT_THROW(firststage::parse_gcode("G1 X1 Y1\nM98 P100\n", "t.nc"), firststage::InputError);
}

}  // namespace
}  // namespace ncinterp::test
