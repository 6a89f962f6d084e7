// The batch core: cleaning presets, manifests, per-take reports (issue 17).
#include "test_support.h"

#include "mocap/base/content_hash.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/batch/archive_summary.h"
#include "mocap/batch/batch_runner.h"
#include "mocap/batch/clean_preset.h"
#include "mocap/batch/take_manifest.h"
#include "mocap/batch/take_report.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace mocap {
namespace {

namespace fs = std::filesystem;

std::string errorOf(const std::function<void()>& f)
{
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

TEST(ContentHash, IsStableAndSeesEveryByte)
{
  EXPECT_EQ(hashText(contentHash("")).size(), 16u);
  EXPECT_EQ(contentHash("mocap"), contentHash("mocap"));
  std::string bytes(1000, 'a');
  const std::uint64_t whole = contentHash(bytes);
  for (std::size_t i : {0u, 7u, 8u, 500u, 999u}) {
    std::string changed = bytes;
    changed[i] = 'b';
    EXPECT_NE(contentHash(changed), whole) << i;
  }
  EXPECT_NE(contentHash(bytes.substr(0, 999)), whole);  // the length counts
  EXPECT_EQ(hashText(0x0123456789abcdefULL), "0123456789abcdef");
}

TEST(CleanPreset, RoundTripsEveryOption)
{
  CleanOptions options;
  options.stabilizeLabels = {"head1", "head2", "head3"};
  options.keepStabilized = true;
  options.spikes->method = SpikeMethod::Paper;
  options.spikes->factor = 2.25;
  options.spikes->maxPasses = 4;
  options.fill->method = FillMethod::Pca;
  options.fill->maxGap = 40;
  options.fill->extrapolate = true;
  options.fill->minValidFraction = 0.35;
  options.fill->neighbours = 9;
  options.smooth->method = SmoothMethod::SavGol;
  options.smooth->savgolWindow = 11;
  options.smooth->savgolDegree = 4;
  options.smooth->gcvsplMode = SmoothingSplineMode::Cutoff;
  const std::string json = cleanPresetJson(options);
  const CleanOptions back = parseCleanPreset(json, "p.json");
  EXPECT_EQ(cleanPresetJson(back), json);
  EXPECT_EQ(back.stabilizeLabels, options.stabilizeLabels);
  EXPECT_TRUE(back.keepStabilized);
  EXPECT_EQ(back.spikes->method, SpikeMethod::Paper);
  EXPECT_EQ(back.spikes->factor, 2.25);
  EXPECT_EQ(back.fill->method, FillMethod::Pca);
  EXPECT_EQ(back.fill->maxGap, 40);
  EXPECT_EQ(back.fill->neighbours, 9);
  EXPECT_TRUE(back.smooth.has_value() && *back.smooth == *options.smooth);

  options.spikes.reset();
  options.smooth.reset();
  const CleanOptions off = parseCleanPreset(cleanPresetJson(options), "p.json");
  EXPECT_FALSE(off.spikes);
  EXPECT_FALSE(off.smooth);
  EXPECT_TRUE(off.fill);
}

TEST(CleanPreset, LeftOutKeysAreTheDefaultsAndTheHashIsOfTheCanonicalForm)
{
  const CleanOptions defaults = parseCleanPreset("{}", "p.json");
  EXPECT_EQ(cleanPresetJson(defaults), cleanPresetJson(CleanOptions{}));
  const CleanOptions spelled =
      parseCleanPreset(R"({"smooth": {"method": "gcvspl"},   "fill":{"neighbours":6,"method":"auto"}})", "p.json");
  EXPECT_EQ(cleanPresetHash(spelled), cleanPresetHash(CleanOptions{}));
  const CleanOptions other = parseCleanPreset(R"({"fill": {"neighbours": 7}})", "p.json");
  EXPECT_NE(cleanPresetHash(other), cleanPresetHash(CleanOptions{}));
}

TEST(CleanPreset, RefusesUnknownKeysAndBadValuesNamingTheKey)
{
  const auto error = [](const std::string& json) { return errorOf([&] { (void)parseCleanPreset(json, "p.json"); }); };
  EXPECT_NE(error(R"({"smoth": {}})").find("unknown key 'smoth'"), std::string::npos);
  EXPECT_NE(error(R"({"fill": {"max_gap": 3}})").find("preset fill: unknown key 'max_gap'"), std::string::npos);
  EXPECT_NE(error(R"({"spikes": {"factor": "big"}})").find("preset spikes.factor"), std::string::npos);
  EXPECT_NE(error(R"({"spikes": {"factor": -1}})").find("preset spikes.factor: -1 not in"), std::string::npos);
  EXPECT_NE(error(R"({"fill": {"method": "magic"}})").find("preset fill.method: unknown value 'magic'"),
            std::string::npos);
  EXPECT_NE(error(R"({"fill": {"neighbours": 2.5}})").find("preset fill.neighbours: 2.5 is not a whole number"),
            std::string::npos);
  EXPECT_NE(error(R"({"fill": {"extrapolate": 1}})").find("preset fill.extrapolate must be true or false"),
            std::string::npos);
  EXPECT_NE(error(R"({"smooth": {"savgol_window": 10}})").find("preset smooth.savgol_window: 10 is not odd"),
            std::string::npos);
  EXPECT_NE(error(R"({"spikes": {"method": "off", "factor": 2}})").find("preset spikes: unknown key 'factor'"),
            std::string::npos);
  EXPECT_NE(error(R"({"version": 2})").find("preset version: 2 is newer"), std::string::npos);
  EXPECT_NE(error(R"([1])").find("preset must be an object"), std::string::npos);
  EXPECT_THROW((void)parseCleanPreset("{", "p.json"), FormatError);
}

TEST(Manifest, ReadsLinesRelativeToItsFolderAndRunsRepeatsOnce)
{
  test::TempDir dir;
  fs::create_directories(dir.file("takes/a"));
  writeFileAtomically(dir.file("takes/a/one.c3d"), "x");
  writeFileAtomically(dir.file("takes/two.trc"), "x");
  writeFileAtomically(dir.file("takes/list.txt"),
                      "# the session\n\na/one.c3d\n  two.trc  \n./a/../a/one.c3d\n" + dir.file("takes/missing.c3d").string() +
                          "\n");
  const TakeManifest manifest = readManifest(dir.file("takes/list.txt"));
  ASSERT_EQ(manifest.takes.size(), 3u);
  EXPECT_EQ(manifest.takes[0].relative, fs::path("a/one.c3d"));
  EXPECT_EQ(manifest.takes[0].line, 3u);
  EXPECT_EQ(manifest.takes[1].relative, fs::path("two.trc"));
  EXPECT_EQ(manifest.takes[2].relative, fs::path("missing.c3d"));  // kept: the batch reports it
  EXPECT_EQ(manifest.root, fs::absolute(dir.file("takes")).lexically_normal());
  ASSERT_EQ(manifest.warnings.size(), 1u);
  EXPECT_NE(manifest.warnings[0].find(":5: repeats line 3"), std::string::npos) << manifest.warnings[0];

  const TakeOutputs outputs = takeOutputs(manifest.takes[0], "out");
  EXPECT_EQ(outputs.take, fs::path("out/a/one.c3d"));
  EXPECT_EQ(outputs.report, fs::path("out/a/one.c3d.report.json"));

  writeFileAtomically(dir.file("empty.txt"), "# nothing\n\n");
  EXPECT_THROW((void)readManifest(dir.file("empty.txt")), InvalidArgument);
  EXPECT_THROW((void)readManifest(dir.file("nowhere.txt")), IoError);
}

TEST(Manifest, SearchesAFolderSortedAndDoesNotFollowALinkLoop)
{
  test::TempDir dir;
  fs::create_directories(dir.file("archive/day2/s1"));
  fs::create_directories(dir.file("archive/day1"));
  writeFileAtomically(dir.file("archive/day2/s1/b.C3D"), "x");
  writeFileAtomically(dir.file("archive/day1/a.trc"), "x");
  writeFileAtomically(dir.file("archive/day1/notes.txt"), "x");
  fs::create_directory_symlink(dir.file("archive"), dir.file("archive/day2/s1/loop"));
  fs::create_directories(dir.file("archive/out"));
  writeFileAtomically(dir.file("archive/out/old.c3d"), "x");
  const TakeManifest manifest = readManifest(dir.file("archive"), dir.file("archive/out"));
  ASSERT_EQ(manifest.takes.size(), 2u);
  EXPECT_EQ(manifest.takes[0].relative, fs::path("day1/a.trc"));
  EXPECT_EQ(manifest.takes[1].relative, fs::path("day2/s1/b.C3D"));
  ASSERT_EQ(manifest.warnings.size(), 1u);
  EXPECT_NE(manifest.warnings[0].find("loop: a link to"), std::string::npos) << manifest.warnings[0];
  EXPECT_NE(manifest.warnings[0].find("(a folder loop); not followed"), std::string::npos);
}

TEST(TakeReport, RoundTripsThroughJson)
{
  TakeReport report;
  report.input = "/archive/a.c3d";
  report.output = "a.c3d";
  report.inputHash = "0123456789abcdef";
  report.presetHash = cleanPresetHash(CleanOptions{});
  report.inputBytes = 1234;
  report.frames = 300;
  report.frameRate = 100;
  report.validBefore = 0.9;
  report.validAfter = 0.95;
  report.spikes = 3;
  report.filledGaps = 2;
  report.unfilledGaps = 1;
  report.missingMarkers = {"m2"};
  report.markers = {{"m1", 0.9, 1.0, {5, 25}, 3, 2, 0}, {"m2", 0.0, 0.0, {300}, 0, 0, 1}};
  report.timings.total = 0.5;
  const std::string json = takeReportJson(report);
  const TakeReport back = parseTakeReport(json, "r.json");
  EXPECT_EQ(takeReportJson(back), json);
  EXPECT_EQ(back.markers.at(0).gapLengths, (std::vector<std::int64_t>{5, 25}));
  EXPECT_FALSE(back.failed());

  TakeReport failed = report;
  failed.error = "a.c3d: truncated";
  const TakeReport failedBack = parseTakeReport(takeReportJson(failed), "r.json");
  EXPECT_EQ(failedBack.error, "a.c3d: truncated");
  EXPECT_TRUE(failedBack.markers.empty());
  EXPECT_THROW((void)parseTakeReport(R"({"format": "other"})", "r.json"), InvalidArgument);
}

TEST(BatchRunner, HandsOutTheLargestTakesFirst)
{
  test::TempDir dir;
  writeFileAtomically(dir.file("small.c3d"), std::string(10, 'x'));
  writeFileAtomically(dir.file("large.c3d"), std::string(300, 'x'));
  writeFileAtomically(dir.file("medium.c3d"), std::string(100, 'x'));
  writeFileAtomically(dir.file("also_medium.c3d"), std::string(100, 'x'));
  writeFileAtomically(dir.file("list.txt"), "small.c3d\nmissing.c3d\nmedium.c3d\nlarge.c3d\nalso_medium.c3d\n");
  const TakeManifest manifest = readManifest(dir.file("list.txt"));
  ASSERT_EQ(manifest.takes.size(), 5u);
  // Ties keep the manifest's order; the missing take (size unknown) goes with the smallest.
  EXPECT_EQ(batchTakeOrder(manifest), (std::vector<std::size_t>{3, 2, 4, 0, 1}));
}

TEST(BatchRunner, RefusesAnOutDirThatIsTheInputsFolder)
{
  test::TempDir dir;
  writeFileAtomically(dir.file("list.txt"), "a.c3d\n");
  const TakeManifest manifest = readManifest(dir.file("list.txt"));
  EXPECT_THROW(prepareOutDir(manifest, dir.path()), InvalidArgument);
  writeFileAtomically(dir.file("file"), "x");
  EXPECT_THROW(prepareOutDir(manifest, dir.file("file") / "out"), IoError);
}

TEST(ArchiveSummary, GroupsFailuresByReasonWhateverTakeTheErrorNames)
{
  const auto take = [](const std::string& name, const std::string& error) {
    TakeReport report;
    report.input = "/archive/" + name;
    report.output = name;
    report.error = error;
    return report;
  };
  const std::string missing = "the take has no marker labelled 'head1'";
  ArchiveSummary summary;
  summary.reports = {take("a.c3d", missing), take("b.c3d", ""), take("c.c3d", "/archive/c.c3d: truncated"),
                     take("d.c3d", missing), take("e.c3d", "e.c3d: truncated"), take("f.c3d", missing)};
  const std::vector<FailureGroup> groups = failuresByReason(summary);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].reason, missing);
  EXPECT_EQ(groups[0].takes, (std::vector<std::size_t>{0, 3, 5})) << "the largest group first";
  EXPECT_EQ(groups[1].reason, "truncated") << "the take's own name is no part of the reason";
  EXPECT_EQ(groups[1].takes, (std::vector<std::size_t>{2, 4}));
  const std::string html = archiveSummaryHtml(summary);
  EXPECT_NE(html.find("<table id=\"failures\">"), std::string::npos);
  EXPECT_NE(html.find("<td>3</td><td>a.c3d, d.c3d, f.c3d</td>"), std::string::npos);
  EXPECT_NE(archiveSummaryJson(summary).find("\"failures_by_reason\""), std::string::npos);
}

} // namespace
} // namespace mocap
