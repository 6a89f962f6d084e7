// Model outputs are not markers (issue 30): the joint angles, forces, moments and powers a Vicon
// Nexus file stores as points are kept in the take and the written file, and left out of gap
// lists, cleaning, layout planning and statistics. Each test reads a Nexus-style file built here.
#include "foreign_takes.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/batch/take_report.h"
#include "mocap/cleaning/clean_pipeline.h"
#include "mocap/io/c3d_reader.h"
#include "mocap/io/bvh_writer.h"
#include "mocap/io/c3d_writer.h"
#include "mocap/io/csv_writer.h"
#include "mocap/io/take_io.h"
#include "mocap/io/trc_io.h"
#include "mocap/layout/layout_frames.h"
#include "mocap/model/gaps.h"
#include "mocap/model/marker_edits.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/marker_set.h"
#include "mocap/model/take_slice.h"

#include <gtest/gtest.h>

#include <cstring>

namespace mocap {
namespace {

const std::vector<std::string> kMarkers = {"LASI", "RASI", "LPSI", "RPSI"};
const std::vector<std::string> kOutputs = {"LHipAngles", "RHipAngles", "LHipForce", "LHipMoment", "LHipPower"};

Take readBack(const Take& take)
{
  const std::string bytes = encodeC3d(take);
  return parseC3d(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "nexus.c3d");
}

/// The Nexus-style take as read from its file: the types come from POINT:ANGLES... only.
Take nexusTake()
{
  return readBack(test::nexusCleaningTake());
}

/// True when point `m` holds the same bytes in both takes (positions, validity, residuals,
/// camera masks, states).
bool sameBytes(const Take& a, const Take& b, Eigen::Index m)
{
  const auto frames = static_cast<std::size_t>(a.frameCount());
  return a.frameCount() == b.frameCount() &&
         std::memcmp(a.trajectory(m).data(), b.trajectory(m).data(), frames * 3 * sizeof(double)) == 0 &&
         (a.valid().col(m) == b.valid().col(m)).all() &&
         std::memcmp(a.residuals().col(m).data(), b.residuals().col(m).data(), frames * sizeof(double)) == 0 &&
         (a.cameraMasks().col(m) == b.cameraMasks().col(m)).all() && (a.states().col(m) == b.states().col(m)).all();
}

TEST(ModelOutputs, TheFileSaysWhichPointsAreMarkers)
{
  const Take take = nexusTake();
  using T = PointType;
  EXPECT_EQ(test::pointTypes(take), (std::vector<T>{T::Marker, T::Marker, T::Marker, T::Marker, T::Angle, T::Angle,
                                              T::Force, T::Moment, T::Power}));
  EXPECT_EQ(markerPoints(take), (std::vector<Eigen::Index>{0, 1, 2, 3}));
  EXPECT_EQ(markerLabels(take), kMarkers);
  EXPECT_EQ(modelOutputPoints(take), (std::vector<Eigen::Index>{4, 5, 6, 7, 8}));
  for (const Eigen::Index m : modelOutputPoints(take))
    EXPECT_EQ(take.label(m), kOutputs[static_cast<std::size_t>(m - 4)]);
  EXPECT_EQ(describeModelOutputs(take), "5 model outputs (2 angles, 1 force, 1 moment, 1 power)");
  EXPECT_EQ(describeModelOutputs(readBack(test::distinctValuesTake(3, 5))), "");
}

TEST(ModelOutputs, CleaningLeavesThemByteIdentical)
{
  const Take read = nexusTake();
  Take take = read;
  CleanOptions options;  // the default clean (spikes, fill, smooth) with head stabilization
  options.stabilizeLabels = kMarkers;
  const CleanReport report = cleanTake(take, options);
  for (const Eigen::Index m : modelOutputPoints(read))
    EXPECT_TRUE(sameBytes(read, take, m)) << read.label(m) << " was changed by cleaning";
  EXPECT_EQ(report.modelOutputs, modelOutputPoints(read));
  for (const SpikeFlag& flag : report.spikes)
    EXPECT_TRUE(isMarker(read, flag.marker)) << read.label(flag.marker) << " flagged";
  ASSERT_EQ(report.gaps.size(), 4u) << "one gap per marker, none of the outputs";
  for (const GapFillReport& gap : report.gaps) {
    EXPECT_TRUE(isMarker(read, gap.gap.marker));
    EXPECT_TRUE(gap.filled) << read.label(gap.gap.marker) << ": " << gap.reason;
  }
  // The markers were cleaned: their gaps are filled.
  EXPECT_TRUE(take.valid().leftCols(4).all());
  // The jump in frame 120 moves the four markers as one rigid body: with them as head markers it
  // is head motion and kept; cleaned without stabilization it is a spike of each, repaired.
  const auto offMidpoint = [](const Take& t) {
    return (t.position(120, 0) - 0.5 * (t.position(119, 0) + t.position(121, 0))).norm();
  };
  Take plain = read;
  (void)cleanTake(plain, CleanOptions{});
  EXPECT_GT(offMidpoint(read), 50.0);
  EXPECT_LT(offMidpoint(plain), 10.0) << "the spike of LASI stayed";
  for (const Eigen::Index m : modelOutputPoints(read))
    EXPECT_TRUE(sameBytes(read, plain, m)) << read.label(m) << " was changed by cleaning";
}

TEST(ModelOutputs, GapsAndFillsLeaveThemOut)
{
  const Take take = nexusTake();
  const std::vector<Gap> gaps = findGaps(take);
  ASSERT_EQ(gaps.size(), 4u);
  for (const Gap& gap : gaps)
    EXPECT_TRUE(isMarker(take, gap.marker)) << take.label(gap.marker);
  // Asked for the gaps of every point (a view showing the outputs), fill leaves the outputs' open
  // and fills the markers' exactly as on a take without outputs: no output serves as a neighbour.
  std::vector<Eigen::Index> all(static_cast<std::size_t>(take.markerCount()));
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    all[static_cast<std::size_t>(m)] = m;
  const std::vector<Gap> everyGap = findGaps(take, all);
  ASSERT_EQ(everyGap.size(), 9u);
  FillOptions options;
  options.method = FillMethod::Pca;
  const FillResult filled = fillGaps(take, everyGap, options);
  ASSERT_EQ(filled.gaps.size(), 9u);
  for (std::size_t i = 0; i < everyGap.size(); ++i) {
    const GapFillReport& report = filled.gaps[i];
    EXPECT_EQ(report.gap.marker, everyGap[i].marker) << "reports follow the gaps asked for";
    if (isMarker(take, report.gap.marker)) {
      EXPECT_TRUE(report.filled) << report.reason;
    } else {
      EXPECT_FALSE(report.filled);
      EXPECT_EQ(report.cause, UnfilledCause::ModelOutput);
      EXPECT_NE(report.reason.find("a model output"), std::string::npos) << report.reason;
    }
  }
  const FillResult markersOnly = fillGaps(subsetTake(take, kMarkers), options);
  ASSERT_EQ(filled.patches.size(), markersOnly.patches.size());
  for (std::size_t i = 0; i < filled.patches.size(); ++i) {
    EXPECT_EQ(filled.patches[i].marker, markersOnly.patches[i].marker) << "markers come first in this take";
    EXPECT_EQ(filled.patches[i].positions, markersOnly.patches[i].positions);
  }
  EXPECT_DOUBLE_EQ(markerValidFraction(take), 1.0 - 5.0 / static_cast<double>(take.frameCount()));
}

TEST(ModelOutputs, HeadStabilizationAndPlanningUseMarkersOnly)
{
  const Take take = nexusTake();
  try {
    (void)estimateHeadMotion(take, {0, 1, 4});
    FAIL() << "stabilized on a joint angle";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("LHipAngles is a model output (angle), not a marker"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(defaultPlannedLabels(take, {}), kMarkers);
  EXPECT_EQ(markerSetFromTake(take).labels, kMarkers);
  for (const Eigen::Index m : guessHeadReferenceMarkers(take))
    EXPECT_TRUE(isMarker(take, m)) << take.label(m);
}

TEST(ModelOutputs, BatchStatisticsLeaveThemOut)
{
  Take take = nexusTake();
  TakeReport report;
  report.validBefore = markerValidFraction(take);  // as the batch runner sets it
  std::vector<MarkerQuality> before = qualityBefore(take);
  const CleanReport cleaning = cleanTake(take, CleanOptions{});
  recordCleaning(report, std::move(before), take, cleaning);
  std::vector<std::string> labels;
  for (const MarkerQuality& marker : report.markers)
    labels.push_back(marker.label);
  EXPECT_EQ(labels, kMarkers);
  for (const MarkerQuality& marker : report.markers) {
    EXPECT_DOUBLE_EQ(marker.validBefore, 1.0 - 5.0 / static_cast<double>(take.frameCount())) << marker.label;
    EXPECT_EQ(marker.gapLengths, std::vector<std::int64_t>{5}) << marker.label;
  }
  EXPECT_DOUBLE_EQ(report.validAfter, 1.0) << "the outputs' gaps stay open and do not count";
  EXPECT_EQ(report.filledGaps, 4);
  EXPECT_EQ(report.unfilledGaps, 0);
  EXPECT_EQ(report.modelOutputs, 5);
  EXPECT_TRUE(report.missingMarkers.empty());
  const TakeReport back = parseTakeReport(takeReportJson(report), "report.json");
  EXPECT_EQ(back.modelOutputs, 5);
}

TEST(ModelOutputs, TypesSurviveWritingSlicingAndSubsets)
{
  // Types set in code, with no list in the parameters: the writer writes the lists.
  Take take = test::distinctValuesTake(6, 20);
  take.setPointType(1, PointType::Angle);
  take.setPointType(2, PointType::Force);
  take.setPointType(3, PointType::Moment);
  take.setPointType(4, PointType::Power);
  take.setPointType(5, PointType::Other);
  Take back = readBack(take);
  EXPECT_EQ(test::pointTypes(back), test::pointTypes(take));
  EXPECT_EQ(back.parameters().strings("POINT", "ANGLES"), (std::vector<std::string>{"P2"}));
  EXPECT_EQ(back.parameters().strings("POINT", "OTHERS"), (std::vector<std::string>{"P6"}));

  // Edited: an output renamed, another removed, a marker inserted; the lists follow the take.
  back.setLabel(1, "LKneeAngles");
  (void)back.removeMarker(2);
  MarkerColumn column = back.column(0);
  column.label = "NEW";
  back.insertMarker(1, std::move(column));
  const Take again = readBack(back);
  EXPECT_EQ(test::pointTypes(again), test::pointTypes(back));
  EXPECT_EQ(again.parameters().strings("POINT", "ANGLES"), (std::vector<std::string>{"LKneeAngles"}));
  EXPECT_EQ(again.parameters().strings("POINT", "FORCES"), (std::vector<std::string>{}));

  const Take nexus = nexusTake();
  EXPECT_EQ(test::pointTypes(sliceFrames(nexus, 10, 50)), test::pointTypes(nexus));
  EXPECT_EQ(test::pointTypes(readBack(sliceFrames(nexus, 10, 50))), test::pointTypes(nexus));
  const Take subset = subsetTake(nexus, {"LHipForce", "LASI"});
  EXPECT_EQ(test::pointTypes(subset), (std::vector<PointType>{PointType::Force, PointType::Marker}));

  // A TRC file holds marker positions: the outputs are not written as markers.
  const Take trc = parseTrc(formatTrc(nexus), "nexus.trc");
  EXPECT_EQ(trc.labels(), kMarkers);
  EXPECT_THROW((void)formatTrc(subsetTake(nexus, {"LHipForce"})), InvalidArgument);
}

TEST(ModelOutputs, MarkerOnlyFormatsLeaveThemOutAndSaySo)
{
  const Take nexus = nexusTake();
  // A BVH joint is a position: only the markers become joints.
  const std::string bvh = formatBvh(nexus);
  for (const std::string& marker : kMarkers)
    EXPECT_NE(bvh.find("JOINT " + marker + "\n"), std::string::npos) << marker;
  EXPECT_EQ(bvh.find("JOINT LHipAngles"), std::string::npos);
  EXPECT_EQ(bvh.find("JOINT LHipPower"), std::string::npos);
  EXPECT_EQ(bvh, formatBvh(subsetTake(nexus, kMarkers)));
  EXPECT_THROW((void)formatBvh(subsetTake(nexus, {"LHipForce"})), InvalidArgument);

  // Saying what is left out: TRC and BVH name the outputs; C3D and CSV hold them.
  const std::string trcNote = leftOutOnWriting(nexus, TakeFormat::Trc);
  EXPECT_NE(trcNote.find("the TRC file holds marker positions only: 5 model outputs (2 angles, 1 force, 1 moment, "
                         "1 power) not written"),
            std::string::npos)
      << trcNote;
  EXPECT_NE(leftOutOnWriting(nexus, TakeFormat::Bvh).find("the BVH file"), std::string::npos);
  EXPECT_EQ(leftOutOnWriting(nexus, TakeFormat::C3d), "");
  EXPECT_EQ(leftOutOnWriting(nexus, TakeFormat::Csv), "");
  EXPECT_EQ(leftOutOnWriting(subsetTake(nexus, kMarkers), TakeFormat::Trc), "");
  EXPECT_NE(formatCsv(nexus).find("LHipAngles:X"), std::string::npos) << "a CSV table keeps every point";
}

TEST(ModelOutputs, AHostileTypeListCannotRewriteTheLabels)
{
  Take take = test::distinctValuesTake(3, 5);
  take.parameters().set("POINT", C3dParameter::makeStrings("TYPE_GROUPS", {"LABELS", "ANGLE"}));
  const Take read = readBack(take);
  EXPECT_EQ(modelOutputPoints(read), std::vector<Eigen::Index>{}) << "POINT:LABELS is no type list";
  EXPECT_EQ(read.labels(), take.labels());
}

} // namespace
} // namespace mocap
