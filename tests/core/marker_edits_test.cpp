#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/base/error.h"
#include "mocap/model/marker_edits.h"

#include <gtest/gtest.h>

#include <cstring>

namespace mocap {
namespace {

// Every per-sample array and the labels, compared exactly (positions bit for bit, NaN included).
void expectIdentical(const Take& a, const Take& b)
{
  ASSERT_EQ(a.labels(), b.labels());
  ASSERT_EQ(a.frameCount(), b.frameCount());
  const auto count = static_cast<std::size_t>(a.markerCount() * a.frameCount() * 3);
  EXPECT_EQ(std::memcmp(a.positionData(), b.positionData(), count * sizeof(double)), 0);
  EXPECT_TRUE((a.valid() == b.valid()).all());
  EXPECT_TRUE((a.residuals() == b.residuals()).all());
  EXPECT_TRUE((a.cameraMasks() == b.cameraMasks()).all());
  EXPECT_TRUE((a.states() == b.states()).all());
}

TEST(MarkerEdits, RemoveThenInsertRestoresTheTakeBitForBit)
{
  Take take = readC3d(test::sampleTake());
  take.setState(10, 5, SampleState().with(SampleOperation::Smoothed));
  const Take original = take;
  for (const Eigen::Index marker : {Eigen::Index{0}, Eigen::Index{17}, take.markerCount() - 1}) {
    const std::string label = take.label(marker);
    const Eigen::Vector3d position = take.position(900, marker);
    MarkerColumn removed = take.removeMarker(marker);
    EXPECT_EQ(take.markerCount(), original.markerCount() - 1);
    EXPECT_FALSE(take.markerIndex(label));
    EXPECT_EQ(removed.label, label);
    EXPECT_EQ(Eigen::Vector3d(removed.positions.row(900)), position);
    // The markers after it moved down one index with their data.
    if (marker + 1 < original.markerCount()) {
      EXPECT_EQ(take.position(900, marker), original.position(900, marker + 1));
    }
    take.insertMarker(marker, std::move(removed));
    expectIdentical(take, original);
  }
}

TEST(MarkerEdits, InsertRejectsMismatchedOrDuplicateColumnsAndLeavesTheTakeAlone)
{
  Take take({"a", "b", "c"}, 5, 100.0);
  const Take original = take;
  MarkerColumn duplicate = take.column(1);
  EXPECT_THROW(take.insertMarker(0, duplicate), InvalidArgument);
  MarkerColumn shorter = take.column(1);
  shorter.label = "d";
  shorter.positions.conservativeResize(4, 3);
  EXPECT_THROW(take.insertMarker(0, shorter), InvalidArgument);
  MarkerColumn unnamed = take.column(1);
  unnamed.label.clear();
  EXPECT_THROW(take.insertMarker(0, unnamed), InvalidArgument);
  MarkerColumn fine = take.column(1);
  fine.label = "d";
  EXPECT_THROW(take.insertMarker(4, fine), InvalidArgument);
  EXPECT_THROW(take.insertMarker(-1, fine), InvalidArgument);
  EXPECT_THROW(static_cast<void>(take.removeMarker(3)), InvalidArgument);
  expectIdentical(take, original);
  take.insertMarker(3, fine);
  EXPECT_EQ(take.label(3), "d");
}

TEST(MarkerEdits, RemovingTheOnlyMarkerLeavesAnEmptyTake)
{
  Take take({"a"}, 3, 100.0);
  take.setPosition(1, 0, {1, 2, 3});
  MarkerColumn column = take.removeMarker(0);
  EXPECT_TRUE(take.empty());
  take.insertMarker(0, std::move(column));
  EXPECT_EQ(take.position(1, 0), Eigen::Vector3d(1, 2, 3));
}

TEST(MarkerEdits, AveragedMarkerIsTheMeanWhereAllSourcesAreValid)
{
  Take take({"a", "b", "c"}, 4, 100.0);
  for (Eigen::Index f = 0; f < 4; ++f) {
    const auto t = static_cast<double>(f);
    take.setPosition(f, 0, {t, 0, 0});
    take.setPosition(f, 1, {0, 2 * t, 4});
    take.valid()(f, 0) = take.valid()(f, 1) = true;
  }
  take.valid()(2, 1) = false;
  const MarkerColumn mid = averagedMarker(take, {0, 1}, "mid");
  EXPECT_EQ(mid.label, "mid");
  EXPECT_EQ(Eigen::Vector3d(mid.positions.row(3)), Eigen::Vector3d(1.5, 3, 2));
  EXPECT_TRUE(mid.valid(1));
  EXPECT_FALSE(mid.valid(2));
  EXPECT_EQ(mid.residuals(2), -1.0);
  EXPECT_EQ(mid.states[1], SampleOrigin::Edited);
  take.insertMarker(take.markerCount(), mid);
  EXPECT_EQ(*take.markerIndex("mid"), 3);
  EXPECT_THROW(static_cast<void>(averagedMarker(take, {}, "x")), InvalidArgument);
  EXPECT_THROW(static_cast<void>(averagedMarker(take, {0, 0}, "x")), InvalidArgument);
  EXPECT_THROW(static_cast<void>(averagedMarker(take, {0, 9}, "x")), InvalidArgument);
}

TEST(MarkerEdits, ValidSamplesPatchMovesAFragmentIntoItsMarker)
{
  Take take({"nose", "Unlabeled1"}, 6, 100.0);
  for (Eigen::Index f = 0; f < 3; ++f) {
    take.setPosition(f, 0, {1, 1, 1});
    take.valid()(f, 0) = true;
  }
  for (Eigen::Index f = 3; f < 5; ++f) {
    take.setPosition(f, 1, {2, 2, static_cast<double>(f)});
    take.valid()(f, 1) = true;
  }
  const SamplePatch patch = validSamplesPatch(take, 1, 0);
  EXPECT_EQ(patch.frames, (std::vector<Eigen::Index>{3, 4}));
  applyPatches(take, {patch});
  EXPECT_TRUE(take.valid().col(0).head(5).all());
  EXPECT_FALSE(take.isValid(5, 0));
  EXPECT_EQ(take.position(4, 0), Eigen::Vector3d(2, 2, 4));
  EXPECT_THROW(static_cast<void>(validSamplesPatch(take, 1, 1)), InvalidArgument);
}

TEST(MarkerEdits, SwapOverRangeExchangesOnlyThatRangeAndSwapsBack)
{
  Take take = readC3d(test::sampleTake());
  const Take original = take;
  const Eigen::Index a = *take.markerIndex("section4-1");  // has a gap at 822-863
  const Eigen::Index b = *take.markerIndex("section4-2");
  std::vector<SamplePatch> undo = applyPatches(take, swapMarkersOverRange(take, a, b, 800, 900));
  EXPECT_EQ(take.position(850, a), original.position(850, b));
  EXPECT_EQ(take.isValid(850, b), original.isValid(850, a));
  EXPECT_EQ(take.isValid(850, a), original.isValid(850, b));
  EXPECT_EQ(take.position(799, a), original.position(799, a));
  EXPECT_EQ(take.position(901, b), original.position(901, b));
  for (const Eigen::Index f : {800, 850, 900}) {
    EXPECT_EQ(take.residuals()(f, a), original.residuals()(f, b));
    EXPECT_EQ(take.cameraMasks()(f, a), original.cameraMasks()(f, b));
    EXPECT_EQ(take.cameraMasks()(f, b), original.cameraMasks()(f, a));
    EXPECT_EQ(take.state(f, b), original.state(f, a));
  }
  applyPatches(take, std::move(undo));
  expectIdentical(take, original);
  EXPECT_THROW(static_cast<void>(swapMarkersOverRange(take, a, a, 0, 1)), InvalidArgument);
  EXPECT_THROW(static_cast<void>(swapMarkersOverRange(take, a, b, 5, 4)), InvalidArgument);
  EXPECT_THROW(static_cast<void>(swapMarkersOverRange(take, a, b, 0, take.frameCount())), InvalidArgument);
}

} // namespace
} // namespace mocap

#include "mocap/model/marker_links.h"
#include "mocap/model/marker_set.h"

namespace mocap {
namespace {

TEST(MarkerLinks, NearestNeighboursOnAGridSkipAStrayMarker)
{
  // A 3 × 3 grid 10 mm apart and one stray marker 500 mm away.
  Take take({"a", "b", "c", "d", "e", "f", "g", "h", "i", "stray"}, 2, 100.0);
  for (Eigen::Index m = 0; m < 9; ++m) {
    take.setPosition(1, m, {10.0 * static_cast<double>(m % 3), 10.0 * static_cast<double>(m / 3), 0.0});
    take.valid()(1, m) = true;
  }
  take.setPosition(1, 9, {500, 500, 0});
  take.valid()(1, 9) = true;
  take.valid()(0, 0) = true;
  EXPECT_EQ(mostCompleteFrame(take), 1);
  const auto links = nearestNeighbourLinks(take, 1, 2);
  for (const auto& [a, b] : links) {
    EXPECT_LT(a, b);
    EXPECT_NE(b, 9) << "the stray marker's links are far longer than the median";
    EXPECT_NEAR((take.position(1, a) - take.position(1, b)).norm(), 10.0, 1e-9) << "grid neighbours only";
  }
  EXPECT_GE(links.size(), 9u);
  EXPECT_TRUE(std::is_sorted(links.begin(), links.end()));
  EXPECT_THROW(static_cast<void>(nearestNeighbourLinks(take, 2)), InvalidArgument);
  EXPECT_THROW(static_cast<void>(nearestNeighbourLinks(take, 1, 0)), InvalidArgument);
  EXPECT_TRUE(nearestNeighbourLinks(take, 0).empty()) << "one valid marker links to nothing";
}

} // namespace
} // namespace mocap

namespace mocap {
namespace {

TEST(SubsetTake, KeepsTheNamedMarkersInOrderWithEverySample)
{
  Take source = readC3d(test::sampleTake());
  source.setState(42, *source.markerIndex("section4-2"), SampleOrigin::Filled);
  source.cameraMasks()(7, *source.markerIndex("root-3")) = 0x5a;
  const std::vector<std::string> labels = {"section4-2", "root-3", "section1-1"};
  const Take subset = subsetTake(source, labels);
  ASSERT_EQ(subset.labels(), labels);
  EXPECT_EQ(subset.frameCount(), source.frameCount());
  EXPECT_EQ(subset.frameRate(), source.frameRate());
  EXPECT_EQ(subset.firstFrame(), source.firstFrame());
  EXPECT_EQ(subset.units(), source.units());
  for (Eigen::Index j = 0; j < subset.markerCount(); ++j) {
    const Eigen::Index m = *source.markerIndex(labels[static_cast<std::size_t>(j)]);
    EXPECT_TRUE((subset.valid().col(j) == source.valid().col(m)).all()) << labels[static_cast<std::size_t>(j)];
    EXPECT_TRUE((subset.residuals().col(j) == source.residuals().col(m)).all());
    EXPECT_TRUE((subset.cameraMasks().col(j) == source.cameraMasks().col(m)).all());
    EXPECT_TRUE((subset.states().col(j) == source.states().col(m)).all());
    for (Eigen::Index f = 0; f < source.frameCount(); ++f) {
      if (source.isValid(f, m)) {
        ASSERT_EQ(subset.position(f, j), source.position(f, m)) << f;
      }
    }
  }
  EXPECT_EQ(subset.state(42, 0), SampleOrigin::Filled);
  EXPECT_EQ(subset.cameraMasks()(7, 1), 0x5a);
}

TEST(SubsetTake, RejectsNoLabelsAnUnknownLabelOrARepeatedOne)
{
  const Take source({"a", "b", "c"}, 4, 100.0);
  EXPECT_THROW((void)subsetTake(source, {}), InvalidArgument);
  EXPECT_THROW((void)subsetTake(source, {"a", "z"}), InvalidArgument);
  EXPECT_THROW((void)subsetTake(source, {"b", "a", "b"}), InvalidArgument);
  EXPECT_EQ(subsetTake(source, {"c", "a"}).labels(), (std::vector<std::string>{"c", "a"}));
}

TEST(MarkerEdits, ExchangeFromAFrameIsTheSwapPatchesToTheEnd)
{
  Take take = readC3d(test::sampleTake());
  const Eigen::Index a = *take.markerIndex("section4-1");
  const Eigen::Index b = *take.markerIndex("section4-2");
  take.cameraMasks()(take.frameCount() - 1, a) = 0x15;  // distinct masks, so an exchange shows
  take.cameraMasks()(take.frameCount() - 1, b) = 0x2a;
  take.setState(take.frameCount() - 2, b, SampleOrigin::Filled);
  Take patched = take;
  applyPatches(patched, swapMarkersOverRange(take, a, b, 700, take.frameCount() - 1));
  Take exchanged = take;
  exchangeMarkersFrom(exchanged, a, b, 700);
  expectIdentical(exchanged, patched);
  EXPECT_EQ(exchanged.cameraMasks()(take.frameCount() - 1, a), 0x2a);
  EXPECT_EQ(exchanged.state(take.frameCount() - 2, a), SampleOrigin::Filled);
  exchangeMarkersFrom(exchanged, a, b, 700);
  expectIdentical(exchanged, take);
  Take same = take;
  exchangeMarkersFrom(same, a, a, 0);                 // one marker: nothing to exchange
  exchangeMarkersFrom(same, a, b, take.frameCount());  // from past the last frame: nothing
  expectIdentical(same, take);
  EXPECT_THROW(exchangeMarkersFrom(same, a, take.markerCount(), 0), InvalidArgument);
  EXPECT_THROW(exchangeMarkersFrom(same, a, b, take.frameCount() + 1), InvalidArgument);
  EXPECT_THROW(exchangeMarkersFrom(same, a, b, -1), InvalidArgument);
}

} // namespace
} // namespace mocap
