// Takes that read without error but cannot be what their file meant (issue 30): every point
// marked invalid while holding coordinates, and coordinates in another unit than the file says.
#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/io/take_plausibility.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace mocap {
namespace {

/// `markers` valid markers `spacing` apart along x, moving along y over 20 frames, in `unit`.
Take markersSpanning(Eigen::Index markers, double spacing, LengthUnit unit)
{
  std::vector<std::string> labels;
  for (Eigen::Index m = 0; m < markers; ++m)
    labels.push_back("M" + std::to_string(m));
  Take take(labels, 20, 100.0);
  take.setUnits(unit);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    for (Eigen::Index m = 0; m < markers; ++m)
      take.setPosition(f, m, Eigen::Vector3d(spacing * static_cast<double>(m), 0.01 * spacing * static_cast<double>(f), 1.0));
  take.valid().setConstant(true);
  return take;
}

bool anyContains(const std::vector<std::string>& warnings, const std::string& text)
{
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

TEST(TakePlausibility, AllInvalidPointsThatHoldCoordinatesAreSaid)
{
  // A real SIMI export: residual -1 on every point, coordinates in metres, no POINT:UNITS.
  std::vector<std::string> warnings;
  const Take take = readC3d(test::dataFile("c3d/sample16/basketball.c3d"), &warnings);
  EXPECT_EQ(take.valid().count(), 0);
  EXPECT_TRUE(anyContains(warnings, "every sample is marked invalid (a negative residual), yet 22 marker(s) hold "
                                    "coordinates"));
  EXPECT_TRUE(anyContains(warnings, "the markers span only 4.02 mm (assumed: the file names no unit)"));
  EXPECT_TRUE(anyContains(warnings, "--input-units m"));

  // Invalid samples at the origin are no coordinates: nothing to say.
  Take empty = markersSpanning(4, 30.0, LengthUnit::Millimetre);
  empty.valid().setConstant(false);
  for (Eigen::Index f = 0; f < empty.frameCount(); ++f)
    for (Eigen::Index m = 0; m < empty.markerCount(); ++m)
      empty.setPosition(f, m, Eigen::Vector3d::Zero());
  EXPECT_TRUE(takePlausibilityWarnings(empty, true).empty());
}

TEST(TakePlausibility, CoordinatesInAnotherUnitThanTheFileSaysAreSaid)
{
  // A face in millimetres (150 mm across) and in metres (0.15 m): as they say.
  EXPECT_TRUE(takePlausibilityWarnings(markersSpanning(6, 30.0, LengthUnit::Millimetre), true).empty());
  EXPECT_TRUE(takePlausibilityWarnings(markersSpanning(6, 0.03, LengthUnit::Metre), true).empty());
  // The metre numbers read as millimetres: 0.15 mm across.
  const std::vector<std::string> small = takePlausibilityWarnings(markersSpanning(6, 0.03, LengthUnit::Millimetre), true);
  ASSERT_EQ(small.size(), 1u);
  EXPECT_NE(small[0].find("span only 0.15 mm (the file's unit)"), std::string::npos) << small[0];
  EXPECT_NE(small[0].find("likely in metres"), std::string::npos) << small[0];
  // Millimetre numbers read as metres: 150 m across.
  const std::vector<std::string> large = takePlausibilityWarnings(markersSpanning(6, 30.0, LengthUnit::Metre), false);
  ASSERT_EQ(large.size(), 1u);
  EXPECT_NE(large[0].find("span 150 m (assumed: the file names no unit), larger than any capture volume"),
            std::string::npos)
      << large[0];
  EXPECT_NE(large[0].find("--input-units mm"), std::string::npos) << large[0];
  // Two markers say nothing about a unit (they may sit close together).
  EXPECT_TRUE(takePlausibilityWarnings(markersSpanning(2, 0.03, LengthUnit::Millimetre), true).empty());
}

} // namespace
} // namespace mocap
