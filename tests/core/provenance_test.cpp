// Provenance: sample states and processing history survive C3D and TRC/CSV (sidecar) round
// trips, stored compactly, and foreign files' residual-0 samples are shown as filled.
#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/io/c3d_writer.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/json_writer.h"
#include "mocap/batch/clean_run.h"
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
    take.setState(f, 1, SampleOrigin::Filled);
    take.residuals()(f, 1) = 0.0;
  }
  for (Eigen::Index f = 50; f < 60; ++f)
    take.setState(f, 0, SampleState().with(SampleOperation::Smoothed));
  take.setState(100, 2, SampleOrigin::Edited);
  take.history().push_back(fillStep());
  return take;
}

TEST(Provenance, StateRunsAreRunLengthRanges)
{
  const std::vector<StateRun> runs = stateRuns(processedTake());
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0], (StateRun{0, 50, 10, SampleState().with(SampleOperation::Smoothed)}));
  EXPECT_EQ(runs[1], (StateRun{1, 10, 20, SampleOrigin::Filled}));
  EXPECT_EQ(runs[2], (StateRun{2, 100, 1, SampleOrigin::Edited}));
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
      take.setState(f, m, f % 8 == 0 ? SampleState().with(SampleOperation::Smoothed) : SampleOrigin::Edited);
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
  EXPECT_EQ(reordered.state(55, 2), SampleState().with(SampleOperation::Smoothed));  // "a" is now index 2
  EXPECT_EQ(reordered.state(100, 0), SampleOrigin::Edited);   // "c" is now index 0
  EXPECT_EQ(reordered.state(20, 1), SampleOrigin::Filled);
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
  EXPECT_EQ(back.state(42, 2), SampleOrigin::Filled);
  EXPECT_EQ(back.state(42, 1), SampleOrigin::Measured);
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
  EXPECT_FALSE((back.states() != std::uint8_t{0}).any());
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.back().find("frames"), std::string::npos) << warnings.back();
  writeFileAtomically(dir.file("take.provenance.json"), "not json");
  warnings.clear();
  EXPECT_NO_THROW((void)readTake(dir.file("take.trc"), &warnings));
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.back().find("sidecar"), std::string::npos);
}

/// processedTake plus samples with both an origin and operations: frames 40..49 of "b" filled
/// then smoothed, 120..124 of "c" edited then smoothed and stabilized, 130..139 of "a" measured and
/// stabilized.
Take combinedTake()
{
  Take take = processedTake();
  const SampleState smoothed = SampleState().with(SampleOperation::Smoothed);
  for (Eigen::Index f = 40; f < 50; ++f) {
    take.setState(f, 1, SampleState(SampleOrigin::Filled).with(SampleOperation::Smoothed));
    take.residuals()(f, 1) = 0.0;
  }
  for (Eigen::Index f = 120; f < 125; ++f)
    take.setState(f, 2, SampleState(SampleOrigin::Edited).with(SampleOperation::Smoothed).with(SampleOperation::Stabilized));
  for (Eigen::Index f = 130; f < 140; ++f)
    take.setState(f, 0, SampleState().with(SampleOperation::Stabilized));
  EXPECT_EQ(take.state(55, 0), smoothed);
  return take;
}

TEST(Provenance, OriginAndOperationsAreKeptApart)
{
  SampleState state = SampleOrigin::Filled;
  state = state.with(SampleOperation::Smoothed);
  EXPECT_EQ(state.origin(), SampleOrigin::Filled);
  EXPECT_TRUE(state.has(SampleOperation::Smoothed));
  EXPECT_FALSE(state.has(SampleOperation::Stabilized));
  EXPECT_EQ(state.without(SampleOperation::Smoothed), SampleOrigin::Filled);
  EXPECT_TRUE(SampleState().untouched());
  EXPECT_FALSE(SampleState().with(SampleOperation::Stabilized).untouched());
  // A byte from elsewhere keeps only bits that mean something.
  EXPECT_EQ(SampleState::fromBits(0xF5).bits(), 0x05);
  EXPECT_EQ(SampleState::fromBits(0x02), SampleOrigin::Measured);
}

TEST(Provenance, CountsPerOriginAndPerOperation)
{
  const Take take = combinedTake();
  const std::vector<StateCounts> counts = stateCounts(take);
  EXPECT_EQ(counts[1].filled, 30);  // 20 filled + 10 filled then smoothed
  EXPECT_EQ(counts[1].smoothed, 10);
  EXPECT_EQ(counts[1].smoothedMeasured, 0);
  EXPECT_EQ(counts[1].measured, 170);
  EXPECT_EQ(counts[0].smoothed, 10);
  EXPECT_EQ(counts[0].smoothedMeasured, 10);
  EXPECT_EQ(counts[0].stabilized, 10);
  EXPECT_EQ(counts[0].measured, 200);
  EXPECT_EQ(counts[2].edited, 6);
  EXPECT_EQ(counts[2].smoothed, 5);
  EXPECT_EQ(counts[2].stabilized, 5);
  const StateCounts total = totalCounts(counts);
  EXPECT_EQ(total.measured + total.filled + total.edited, 600);  // every sample is valid here
  JsonWriter json;
  json.beginObject();
  writeStateCountsJson(json, counts[1]);
  json.endObject();
  EXPECT_NE(json.str().find("\"origin\": {\n    \"measured\": 170,\n    \"filled\": 30,\n    \"edited\": 0\n  }"),
            std::string::npos)
      << json.str();
  // The version-1 keys count each sample once, by origin first.
  EXPECT_NE(json.str().find("\"filled\": 30,\n  \"smoothed\": 0,\n  \"edited\": 0,"), std::string::npos) << json.str();
}

TEST(Provenance, OriginAndOperationsSurviveC3dAndSidecar)
{
  const Take take = combinedTake();
  std::vector<std::string> warnings;
  const Take back = reparse(take, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_TRUE((back.states() == take.states()).all());
  EXPECT_EQ(back.state(45, 1), SampleState(SampleOrigin::Filled).with(SampleOperation::Smoothed));
  EXPECT_EQ(back.residuals()(45, 1), 0.0) << "a smoothed fill is still written as computed";
  EXPECT_NE(encodeC3d(take).find("VERSION"), std::string::npos);
  C3dParameterTree tree;
  storeProvenance(take, tree);
  EXPECT_EQ(tree.group("PROCESSING")->find("VERSION")->number(), 2.0);

  test::TempDir dir;
  writeTake(take, dir.file("take.trc"));
  const std::string sidecar = readFileBytes(dir.file("take.provenance.json"));
  EXPECT_NE(sidecar.find("\"version\": 2"), std::string::npos);
  // Marker "b"'s runs: [11, 20, "filled", []] and [41, 10, "filled", ["smoothed"]].
  const JsonValue document = parseJson(sidecar, "sidecar");
  const auto& runs = document.find("markers", "")->array("")[1].find("runs", "")->array("");
  ASSERT_EQ(runs.size(), 2u);
  ASSERT_EQ(runs[1].array("").size(), 4u);
  EXPECT_EQ(runs[1].array("")[0].number(""), 41.0);
  EXPECT_EQ(runs[1].array("")[2].string(""), "filled");
  ASSERT_EQ(runs[1].array("")[3].array("").size(), 1u);
  EXPECT_EQ(runs[1].array("")[3].array("")[0].string(""), "smoothed");
  warnings.clear();
  const Take fromSidecar = readTake(dir.file("take.trc"), &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_TRUE((fromSidecar.states() == take.states()).all());
}

TEST(Provenance, VersionOneGroupStillReads)
{
  // What the first writers stored: one state per sample, 1 filled, 2 smoothed, 3 edited.
  Take take = measuredTake();
  C3dGroup& group = take.parameters().ensureGroup("PROCESSING");
  group.parameters.push_back(C3dParameter::makeInt16("VERSION", {1}, true));
  group.parameters.push_back(C3dParameter::makeStrings("LABELS", {"a", "b", "c"}));
  C3dParameter runs = C3dParameter::makeFloat("STATE_RUNS", {1, 10, 20, 1, 0, 50, 10, 2, 2, 100, 1, 3}, false);
  runs.dimensions = {4, 3};
  group.parameters.push_back(runs);
  const std::vector<C3dParameter> versionOne = group.parameters;  // loading removes the group
  std::vector<std::string> warnings;
  loadProvenance(take, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(take.state(15, 1), SampleOrigin::Filled);
  EXPECT_EQ(take.state(55, 0), SampleState().with(SampleOperation::Smoothed));
  EXPECT_EQ(take.state(100, 2), SampleOrigin::Edited);
  EXPECT_EQ(take.state(5, 1), SampleOrigin::Measured);
  // A code version 1 did not have is skipped with a warning, not misread.
  Take other = measuredTake();
  C3dGroup& bad = other.parameters().ensureGroup("PROCESSING");
  bad.parameters = versionOne;
  bad.find("STATE_RUNS")->numbers[3] = 5;
  warnings.clear();
  loadProvenance(other, &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(other.state(15, 1), SampleOrigin::Measured);
}

TEST(Provenance, UnknownGroupVersionIsAWarning)
{
  Take take = combinedTake();
  C3dParameterTree tree;
  storeProvenance(take, tree);
  tree.group("PROCESSING")->find("VERSION")->numbers = {3};
  Take target = measuredTake();
  target.parameters() = tree;
  std::vector<std::string> warnings;
  loadProvenance(target, &warnings);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.front().find("VERSION 3"), std::string::npos) << warnings.front();
  EXPECT_FALSE((target.states() != std::uint8_t{0}).any());
  EXPECT_EQ(target.history(), take.history()) << "the history is still read";
}

TEST(Provenance, VersionOneSidecarStillReads)
{
  Take take = measuredTake();
  const std::string text = R"({"format": "mocap-studio provenance", "version": 1, "frames": 200, "first_frame": 1,
    "markers": [{"label": "a", "filled": 0, "smoothed": 10, "edited": 0, "runs": [[51, 10, "smoothed"]]},
                {"label": "b", "filled": 20, "smoothed": 0, "edited": 0, "runs": [[11, 20, "filled"]]},
                {"label": "c", "filled": 0, "smoothed": 0, "edited": 1, "runs": [[101, 1, "edited"]]}],
    "history": []})";
  std::vector<std::string> warnings;
  applyProvenanceJson(take, text, "old.provenance.json", &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(take.state(55, 0), SampleState().with(SampleOperation::Smoothed));
  EXPECT_EQ(take.state(15, 1), SampleOrigin::Filled);
  EXPECT_EQ(take.state(100, 2), SampleOrigin::Edited);
  // Names neither version knows are skipped with a warning.
  applyProvenanceJson(take, R"({"format": "mocap-studio provenance", "frames": 200, "first_frame": 1,
    "markers": [{"label": "a", "runs": [[1, 2, "guessed"], [1, 2, "filled", ["polished"]]]}]})",
                      "odd.provenance.json", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings.front().find("2 sample-state run(s)"), std::string::npos) << warnings.front();
}

TEST(Provenance, DefaultCleanOfTheSampleCountsWhatTheHistorySays)
{
  // The default `mocap clean`: spikes repaired, gaps filled, everything smoothed. The smoothing
  // must not hide which samples were invented: the counts by origin equal the history's.
  Take take = readTake(test::sampleTake());
  const StateCounts before = totalCounts(stateCounts(take));
  const std::size_t steps = take.history().size();
  (void)cleanAndRecord(take, CleanOptions{}, "test");
  ASSERT_EQ(take.history().size(), steps + 3);
  const ProcessingStep& repair = take.history()[steps];
  const ProcessingStep& fill = take.history()[steps + 1];
  const ProcessingStep& smooth = take.history()[steps + 2];
  ASSERT_EQ(repair.operation, "repair spikes");
  ASSERT_EQ(fill.operation, "fill gaps");
  ASSERT_EQ(smooth.operation, "smooth");
  ASSERT_GT(repair.samples, 0);
  ASSERT_GT(fill.samples, 0);
  const StateCounts after = totalCounts(stateCounts(take));
  EXPECT_EQ(after.edited - before.edited, repair.samples);
  EXPECT_EQ(after.filled - before.filled, fill.samples);
  EXPECT_EQ(after.smoothed - before.smoothed, smooth.samples);
  // ... and they survive the file the CLI writes.
  test::TempDir dir;
  writeTake(take, dir.file("clean.c3d"));
  const StateCounts reread = totalCounts(stateCounts(readTake(dir.file("clean.c3d"))));
  EXPECT_EQ(reread.edited, after.edited);
  EXPECT_EQ(reread.filled, after.filled);
  EXPECT_EQ(reread.smoothed, after.smoothed);
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

} // namespace
} // namespace mocap
