// Provenance: sample states and processing history survive C3D and TRC/CSV (sidecar) round
// trips, stored compactly, and foreign files' residual-0 samples are shown as filled.
#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/io/c3d_writer.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/cleaning/fill/gap_fill.h"
#include "mocap/model/provenance.h"
#include "mocap/model/sample_patch.h"
#include "mocap/io/take_io.h"
#include "mocap/io/trc_io.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace mocap {
namespace {

Take reparse(const Take& take, std::vector<std::string>* warnings = nullptr)
{
  const std::string bytes = encodeC3d(take);
  return parseC3d(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "provenance.c3d", warnings);
}

/// A 3-marker, 200-frame take, every sample measured with residual 1.5 mm.
Take measuredTake()
{
  Take take({"a", "b", "c"}, 200, 100.0);
  for (Eigen::Index m = 0; m < 3; ++m)
    for (Eigen::Index f = 0; f < 200; ++f) {
      take.setPosition(f, m, Eigen::Vector3d(static_cast<double>(f), static_cast<double>(m), 1.0));
      take.valid()(f, m) = true;
      take.residuals()(f, m) = 1.5;
    }
  return take;
}

ProcessingStep fillStep()
{
  ProcessingStep step;
  step.operation = "fill gaps";
  step.parameters = {{"method", "auto"}, {"max gap", "50 frames (0.5 s)"}};
  step.markers = {"b"};
  step.firstFrame = 11;
  step.lastFrame = 30;
  step.samples = 20;
  step.time = "2026-12-01T19:30:00Z";
  step.tool = "mocap-studio";
  return step;
}

/// Marks frames 10..29 of "b" filled (residual 0 as makePatch gives), 50..59 of "a" smoothed and
/// frame 100 of "c" edited, with one history step.
Take processedTake()
{
  Take take = measuredTake();
  for (Eigen::Index f = 10; f < 30; ++f) {
    take.setState(f, 1, SampleState::Filled);
    take.residuals()(f, 1) = 0.0;
  }
  for (Eigen::Index f = 50; f < 60; ++f)
    take.setState(f, 0, SampleState::Smoothed);
  take.setState(100, 2, SampleState::Edited);
  take.history().push_back(fillStep());
  return take;
}

TEST(Provenance, StateRunsAreRunLengthRanges)
{
  const std::vector<StateRun> runs = stateRuns(processedTake());
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0], (StateRun{0, 50, 10, SampleState::Smoothed}));
  EXPECT_EQ(runs[1], (StateRun{1, 10, 20, SampleState::Filled}));
  EXPECT_EQ(runs[2], (StateRun{2, 100, 1, SampleState::Edited}));
  const std::vector<StateCounts> counts = stateCounts(processedTake());
  EXPECT_EQ(counts[0].smoothed, 10);
  EXPECT_EQ(counts[1].filled, 20);
  EXPECT_EQ(counts[2].edited, 1);
  EXPECT_FALSE(hasProvenance(measuredTake()));
}

TEST(Provenance, StatesAndHistorySurviveC3dRoundTrip)
{
  const Take take = processedTake();
  std::vector<std::string> warnings;
  const Take back = reparse(take, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_TRUE((back.states() == take.states()).all());
  ASSERT_EQ(back.history().size(), 1u);
  EXPECT_EQ(back.history().front(), fillStep());
  // The group becomes the take's state: it is not kept in the tree a second time.
  EXPECT_EQ(back.parameters().group("PROCESSING"), nullptr);
  // Writing the read take again gives the same file.
  EXPECT_EQ(encodeC3d(back), encodeC3d(take));
}

TEST(Provenance, FilledSamplesAreWrittenWithResidualZero)
{
  Take take = processedTake();
  take.residuals()(15, 1) = 2.0;  // a filled sample that still carries a residual
  const Take back = reparse(take);
  EXPECT_EQ(back.residuals()(15, 1), 0.0);
  // A measured sample with a small residual never rounds down to 0 (which would mean computed).
  Take small = measuredTake();
  small.residuals()(5, 0) = 0.2;
  EXPECT_GT(reparse(small).residuals()(5, 0), 0.0);
}

TEST(Provenance, NothingToSayWritesNoGroup)
{
  const std::string bytes = encodeC3d(measuredTake());
  EXPECT_EQ(bytes.find("PROCESSING"), std::string::npos);
  // A stale group from the file read is replaced, not kept.
  Take take = measuredTake();
  take.parameters().ensureGroup("PROCESSING").parameters.push_back(C3dParameter::makeInt16("VERSION", {1}, true));
  EXPECT_EQ(encodeC3d(take).find("PROCESSING"), std::string::npos);
}

TEST(Provenance, ManyRunsAndALongHistorySpanSeveralParameters)
{
  Take take({"a", "b"}, 4000, 100.0);
  for (Eigen::Index f = 0; f < 4000; f += 4)  // 1000 one-frame runs per marker
    for (Eigen::Index m = 0; m < 2; ++m)
      take.setState(f, m, f % 8 == 0 ? SampleState::Smoothed : SampleState::Edited);
  for (int i = 0; i < 300; ++i) {
    ProcessingStep step = fillStep();
    step.operation = "step " + std::to_string(i) + "   with  spaces at the ends  ";
    take.history().push_back(step);
  }
  const std::string bytes = encodeC3d(take);
  const Take back = parseC3d(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "many.c3d");
  EXPECT_TRUE((back.states() == take.states()).all());
  EXPECT_EQ(back.history(), take.history());
  EXPECT_NE(bytes.find("STATE_RUNS8"), std::string::npos);  // 2000 runs / 255 per parameter
  EXPECT_NE(bytes.find("HISTORY2"), std::string::npos);
}

TEST(Provenance, RunsFollowLabelsNotIndices)
{
  // Another tool may reorder the markers: the runs name markers through PROCESSING:LABELS.
  const Take take = processedTake();
  Take reordered({"c", "b", "a"}, 200, 100.0);
  storeProvenance(take, reordered.parameters());
  loadProvenance(reordered, nullptr);
  EXPECT_EQ(reordered.state(55, 2), SampleState::Smoothed);  // "a" is now index 2
  EXPECT_EQ(reordered.state(100, 0), SampleState::Edited);   // "c" is now index 0
  EXPECT_EQ(reordered.state(20, 1), SampleState::Filled);
}

TEST(Provenance, MalformedGroupIsAWarningNotAFailure)
{
  Take take = processedTake();
  C3dParameterTree tree;
  storeProvenance(take, tree);
  C3dParameter* history = tree.group("PROCESSING")->find("HISTORY");
  ASSERT_NE(history, nullptr);
  history->chars.replace(0, 1, "{");  // no longer a JSON array
  Take target = measuredTake();
  target.parameters() = tree;
  std::vector<std::string> warnings;
  loadProvenance(target, &warnings);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.back().find("PROCESSING"), std::string::npos) << warnings.back();
  EXPECT_TRUE(target.history().empty());
}

TEST(Provenance, ForeignResidualZeroSamplesAreShownAsFilled)
{
  Take take = measuredTake();
  for (Eigen::Index f = 40; f < 45; ++f)
    take.residuals()(f, 2) = 0.0;  // another system's gap fill, no PROCESSING group
  std::vector<std::string> warnings;
  const Take back = reparse(take, &warnings);
  EXPECT_EQ(back.state(42, 2), SampleState::Filled);
  EXPECT_EQ(back.state(42, 1), SampleState::Original);
  EXPECT_EQ(stateCounts(back)[2].filled, 5);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings.front().find("residual 0"), std::string::npos);
  // A file whose residuals are all 0 (no residuals recorded) is not marked.
  Take none = measuredTake();
  none.residuals().setZero();
  EXPECT_FALSE(hasProvenance(reparse(none)));
}

TEST(Provenance, SampleTakeFilledSamplesSurviveSaveAndReopen)
{
  Take take = readTake(test::sampleTake());
  FillOptions options;
  options.method = FillMethod::Linear;
  options.maxGap = 20;
  FillResult filled = fillGaps(take, options);
  ASSERT_FALSE(filled.patches.empty());
  Eigen::Index samples = 0;
  for (const SamplePatch& p : filled.patches)
    samples += static_cast<Eigen::Index>(p.size());
  (void)applyPatches(take, std::move(filled.patches));
  take.history().push_back(fillStep());
  test::TempDir dir;
  writeTake(take, dir.file("cleaned.c3d"));
  std::vector<std::string> warnings;
  const Take back = readTake(dir.file("cleaned.c3d"), &warnings);
  Eigen::Index filledBack = 0;
  for (const StateCounts& c : stateCounts(back))
    filledBack += c.filled;
  EXPECT_EQ(filledBack, samples);
  EXPECT_TRUE((back.states() == take.states()).all());
  EXPECT_EQ(back.history(), take.history());
}

TEST(Provenance, TrcAndCsvGetASidecarThatTrcReadsBack)
{
  test::TempDir dir;
  const Take take = processedTake();
  writeTake(take, dir.file("take.trc"));
  writeTake(take, dir.file("other.csv"));
  ASSERT_TRUE(std::filesystem::exists(dir.file("take.provenance.json")));
  ASSERT_TRUE(std::filesystem::exists(dir.file("other.provenance.json")));
  const std::string sidecar = readFileBytes(dir.file("take.provenance.json"));
  EXPECT_NE(sidecar.find("\"filled\": 20"), std::string::npos) << sidecar;
  EXPECT_NE(sidecar.find("\"fill gaps\""), std::string::npos);
  const Take back = readTake(dir.file("take.trc"));
  EXPECT_TRUE((back.states() == take.states()).all());
  EXPECT_EQ(back.history(), take.history());
  // Writing a take without provenance over it removes the stale sidecar.
  writeTake(measuredTake(), dir.file("take.trc"));
  EXPECT_FALSE(std::filesystem::exists(dir.file("take.provenance.json")));
}

TEST(Provenance, SidecarForAnotherTakeIsIgnoredWithAWarning)
{
  test::TempDir dir;
  writeTake(processedTake(), dir.file("take.trc"));
  Take cut({"a", "b", "c"}, 150, 100.0);
  writeTrc(cut, dir.file("take.trc"));  // the TRC changed, the sidecar did not
  std::vector<std::string> warnings;
  const Take back = readTake(dir.file("take.trc"), &warnings);
  EXPECT_FALSE((back.states() != static_cast<std::uint8_t>(SampleState::Original)).any());
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.back().find("frames"), std::string::npos) << warnings.back();
  writeFileAtomically(dir.file("take.provenance.json"), "not json");
  warnings.clear();
  EXPECT_NO_THROW((void)readTake(dir.file("take.trc"), &warnings));
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.back().find("sidecar"), std::string::npos);
}

TEST(Provenance, HeadMarkersSurviveC3dAndSidecarRoundTrips)
{
  Take take = measuredTake();  // no other provenance: the head markers alone make the group
  setHeadMarkers(take, {"c", "a"});
  ASSERT_TRUE(hasProvenance(take));
  std::vector<std::string> warnings;
  const Take back = reparse(take, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(headMarkers(back), (std::vector<std::string>{"c", "a"}));
  EXPECT_EQ(encodeC3d(back), encodeC3d(take)) << "writing the read take again gives the same file";
  // The rest of the group becomes the take's state; with states and history they all come back.
  Take processed = processedTake();
  setHeadMarkers(processed, {"b", "c"});
  const Take both = reparse(processed);
  EXPECT_EQ(headMarkers(both), (std::vector<std::string>{"b", "c"}));
  EXPECT_EQ(both.history(), processed.history());
  setHeadMarkers(processed, {});
  EXPECT_TRUE(headMarkers(processed).empty());
  EXPECT_EQ(reparse(processed).parameters().group("PROCESSING"), nullptr);

  test::TempDir dir;
  writeTake(take, dir.file("take.trc"));
  const std::string sidecar = readFileBytes(dir.file("take.provenance.json"));
  EXPECT_NE(sidecar.find("\"head_markers\""), std::string::npos) << sidecar;
  EXPECT_EQ(headMarkers(readTake(dir.file("take.trc"))), (std::vector<std::string>{"c", "a"}));
}

TEST(Provenance, HeadMarkersTheTakeLacksAreDroppedWithAWarning)
{
  Take take = measuredTake();
  setHeadMarkers(take, {"a", "b"});
  const std::string text = provenanceJson(take);
  Take other({"a", "x", "c"}, 200, 100.0);
  std::vector<std::string> warnings;
  applyProvenanceJson(other, text, "take.provenance.json", &warnings);
  EXPECT_EQ(headMarkers(other), (std::vector<std::string>{"a"}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings.front().find("head marker(s) b"), std::string::npos) << warnings.front();
}

TEST(Provenance, TruncatedFileReportsDataLoss)
{
  const std::string bytes = encodeC3d(measuredTake());
  const std::string cut = bytes.substr(0, bytes.size() - 3 * 4 * 4 * 60);  // drop 60 frames
  std::vector<std::string> warnings, dataLoss;
  const Take back = parseC3d(reinterpret_cast<const unsigned char*>(cut.data()), cut.size(), "cut.c3d", &warnings,
                             &dataLoss);
  EXPECT_EQ(back.frameCount(), 140);
  ASSERT_EQ(dataLoss.size(), 1u);
  EXPECT_NE(dataLoss.front().find("truncated"), std::string::npos);
  // A complete file has no data-loss warning.
  dataLoss.clear();
  (void)parseC3d(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "whole.c3d", nullptr, &dataLoss);
  EXPECT_TRUE(dataLoss.empty());
}

} // namespace
} // namespace mocap
