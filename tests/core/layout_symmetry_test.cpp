#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/base/error.h"
#include "mocap/layout/layout_symmetry.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace mocap {
namespace {

LayoutFrames sampleFrames()
{
  const Take take = readC3d(test::sampleTake());
  LayoutFramesOptions options;
  options.stabilizeLabels = {"root-1", "root-2", "root-3", "root-4", "root-5", "root-6"};
  for (const std::string& label : take.labels())
    if (label.rfind("section", 0) == 0)
      options.markers.push_back(label);
  return collectLayoutFrames({take}, options);
}

Eigen::Index indexOf(const LayoutFrames& frames, const std::string& label)
{
  return std::find(frames.labels.begin(), frames.labels.end(), label) - frames.labels.begin();
}

TEST(LayoutSymmetry, FindsTheSampleFacesMirrorPairsOnItsRestingFrame)
{
  const LayoutFrames frames = sampleFrames();
  const PairDetection detection = detectLayoutPairs(frames);
  // The sample's left/right markers (sectionN-1 ↔ sectionM-1 across the face, and the three-marker
  // rows 10, 13 and 14 whose outer markers mirror each other).
  const MarkerSymmetry& symmetry = detection.symmetry;
  EXPECT_EQ(symmetry.pairs().size(), 13u);
  for (const auto& [a, b] : std::vector<std::pair<std::string, std::string>>{{"section1-1", "section2-1"},
                                                                             {"section5-2", "section6-2"},
                                                                             {"section11-1", "section12-1"},
                                                                             {"section13-1", "section13-3"},
                                                                             {"section14-1", "section14-3"}})
    EXPECT_EQ(symmetry.mirror(indexOf(frames, a)), indexOf(frames, b)) << a << " " << b;
  // Midline markers are their own mirror image.
  EXPECT_EQ(symmetry.mirror(indexOf(frames, "section13-2")), indexOf(frames, "section13-2"));
}

TEST(LayoutSymmetry, FramesWithoutARowAreAnError)
{
  LayoutFrames empty = sampleFrames();
  empty.training.clear();
  empty.test.clear();
  empty.frames.resize(0, empty.frames.cols());
  EXPECT_THROW((void)detectLayoutPairs(empty), InvalidArgument);
}

} // namespace
} // namespace mocap
