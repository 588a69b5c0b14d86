// G-code as CAM posts write it (examples/contours/cam/, in the style of Fusion 360, FreeCAD
// and Estlcam): the machine words are ignored and listed in one warning, and the contour is
// the moves at the cutting depth (the lowest Z, or --cut-z); everything else traverses.
#include <gtest/gtest.h>

#include <cmath>

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

TEST(CamGcode, Fusion360PostTwoDepthPassesTheLastIsTheCut) {
  const firststage::Contour c = firststage::read_contour(kCam + "fusion360_profile.nc", {});
  expect_plate_cut(c);
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
  size_t cuts = 0;
  for (const auto& s : c.segments) cuts += !s.rapid;
  EXPECT_EQ(cuts, 9u);  // the way back to the start of the ramp, then the plate
  EXPECT_NE(c.warnings.at(0).find("G4"), std::string::npos) << c.warnings[0];
}

TEST(CamGcode, CutZChoosesTheDepthAndAnUnreachedDepthIsAnError) {
  firststage::InputOptions io;
  io.cut_z_mm = -1.0;  // both passes of the Fusion file are the cut
  const firststage::Contour c = firststage::read_contour(kCam + "fusion360_profile.nc", io);
  size_t cuts = 0;
  for (const auto& s : c.segments) cuts += !s.rapid;
  EXPECT_EQ(cuts, 16u);
  io.cut_z_mm = -5.0;
  EXPECT_THROW(firststage::read_contour(kCam + "fusion360_profile.nc", io), firststage::InputError);
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
