// `mocap batch`, `mocap clean --manifest --index` and `mocap summarize` end to end (issue 17):
// results independent of --jobs, resume, failures recorded, no partial files, Ctrl+C, GNU parallel.
#include "../core/test_support.h"
#include "shell_run.h"

#include "mocap/base/content_hash.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/io/take_io.h"
#include "mocap/model/data_loss_record.h"
#include "checkout_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

namespace mocap {
namespace {

namespace fs = std::filesystem;
using test::shellQuote;

/// Fixed history time, so two runs write identical takes.
const std::string kEpoch = "SOURCE_DATE_EPOCH=1780000000 ";

test::ShellResult mocap(const std::string& arguments, const test::TempDir& dir, const std::string& environment = kEpoch)
{
  return test::runShell(environment + shellQuote(std::string(checkout::cliProgram())) + " " + arguments, dir.path());
}

/// An archive of real takes in two sessions, and a manifest listing them relative to itself.
struct Archive
{
  explicit Archive(const test::TempDir& dir) : root(dir.file("archive"))
  {
    const std::vector<std::pair<std::string, std::string>> takes = {
        {"c3d/sample01/Eb015pi.c3d", "session1/Eb015pi.c3d"},
        {"c3d/sample01/Eb015vi.c3d", "session1/Eb015vi.c3d"},
        {"c3d/sample02/dec_real.c3d", "session2/day1/dec_real.c3d"},
        {"c3d/sample02/pc_real.c3d", "session2/pc_real.c3d"},
        {"c3d/sample08/TESTAPI.c3d", "session2/TESTAPI.c3d"},
    };
    std::string manifest = "# test archive\n";
    for (const auto& [from, to] : takes) {
      fs::create_directories((root / to).parent_path());
      fs::copy_file(test::dataFile(from), root / to);
      manifest += to + "\n";
      relative.push_back(to);
    }
    writeFileAtomically(root / "takes.txt", manifest);
  }
  fs::path manifest() const { return root / "takes.txt"; }

  fs::path root;
  std::vector<std::string> relative;
};

/// Every regular file below `folder`, by relative path.
std::map<std::string, std::string> filesBelow(const fs::path& folder)
{
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file())
      files[entry.path().lexically_relative(folder).string()] = readFileBytes(entry.path());
  return files;
}

/// Names of temporary files an interrupted atomic write would leave.
std::vector<std::string> temporaries(const fs::path& folder)
{
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.path().filename().string().find(".tmp") != std::string::npos)
      found.push_back(entry.path().string());
  return found;
}

/// A per-take report without its "timings" (the one part that differs between runs).
std::string withoutTimings(const std::string& report)
{
  const std::size_t at = report.find("\"timings\"");
  if (at == std::string::npos)
    return report;
  return report.substr(0, at) + report.substr(report.find('}', at) + 1);
}

const JsonValue& member(const JsonValue& object, const std::string& key)
{
  const JsonValue* value = object.find(key, "test");
  if (value == nullptr)
    throw std::runtime_error("no key " + key);
  return *value;
}

/// The status of each take in OUTDIR/batch.json, by output path.
std::map<std::string, std::string> statuses(const fs::path& outDir)
{
  const JsonValue report = parseJson(readFileBytes(outDir / "batch.json"), "batch.json");
  std::map<std::string, std::string> result;
  for (const JsonValue& take : member(report, "takes").array("takes"))
    result[member(take, "output").string("output")] = member(take, "status").string("status");
  return result;
}

TEST(BatchCli, ResultsAreByteIdenticalWhateverTheNumberOfJobs)
{
  test::TempDir dir;
  const Archive archive(dir);
  const auto one = mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("one")) + " --jobs 1", dir);
  ASSERT_EQ(one.exitCode, 0) << one.err;
  EXPECT_NE(one.out.find("cleaned 5, skipped 0, failed 0"), std::string::npos) << one.out;
  const auto three = mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("three")) + " --jobs 3", dir);
  ASSERT_EQ(three.exitCode, 0) << three.err;

  auto a = filesBelow(dir.file("one")), b = filesBelow(dir.file("three"));
  a.erase("batch.json");
  b.erase("batch.json");
  ASSERT_EQ(a.size(), 10u);  // each take and its report, the tree mirrored
  ASSERT_EQ(b.size(), a.size());
  for (const std::string& take : archive.relative) {
    ASSERT_TRUE(a.count(take)) << take;
    EXPECT_TRUE(a.at(take) == b.at(take)) << take << " differs between --jobs 1 and 3";
    const std::string report = take + ".report.json";
    ASSERT_TRUE(a.count(report));
    EXPECT_EQ(withoutTimings(a.at(report)), withoutTimings(b.at(report)));
    const JsonValue parsed = parseJson(a.at(report), report);
    EXPECT_EQ(member(parsed, "input_hash").string(""),
              hashText(contentHash(readFileBytes(archive.root / take))));
    EXPECT_EQ(member(parsed, "output").string(""), take);
    EXPECT_EQ(member(parsed, "status").string(""), "cleaned");
    EXPECT_GT(member(parsed, "valid_fraction_after").number(""), 0.0);
    EXPECT_FALSE(member(parsed, "markers").array("").empty());
  }
  EXPECT_NE(a.at("session1/Eb015pi.c3d"), readFileBytes(archive.root / "session1/Eb015pi.c3d"));  // it was cleaned
  for (const auto& [take, status] : statuses(dir.file("three")))
    EXPECT_EQ(status, "cleaned") << take;
}

TEST(BatchCli, ResultsAreByteIdenticalWithAndWithoutTheAvx2Kernels)
{
  // The spike detector runs its interior on four-lane AVX2 kernels where the CPU has AVX2;
  // MOCAP_NO_AVX2 rules them out. The two paths must agree bit for bit, on real takes from several
  // systems and on the facial sample, whose spikes the detector flags. (On a CPU without AVX2
  // both runs take the baseline path and this checks nothing more than determinism.)
  test::TempDir dir;
  const Archive archive(dir);
  fs::copy_file(test::sampleTake(), archive.root / "Facial-Sing.c3d");
  writeFileAtomically(archive.manifest(), readFileBytes(archive.manifest()) + "Facial-Sing.c3d\n");
  const auto with = mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("with")), dir);
  ASSERT_EQ(with.exitCode, 0) << with.err;
  const auto without = mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("without")),
                             dir, kEpoch + "MOCAP_NO_AVX2=1 ");
  ASSERT_EQ(without.exitCode, 0) << without.err;
  auto a = filesBelow(dir.file("with")), b = filesBelow(dir.file("without"));
  a.erase("batch.json");
  b.erase("batch.json");
  ASSERT_EQ(a.size(), 12u);
  ASSERT_EQ(b.size(), a.size());
  for (const auto& [name, bytes] : a) {
    ASSERT_TRUE(b.count(name)) << name;
    if (name.size() > 12 && name.compare(name.size() - 12, 12, ".report.json") == 0)
      EXPECT_EQ(withoutTimings(bytes), withoutTimings(b.at(name))) << name;
    else
      EXPECT_TRUE(bytes == b.at(name)) << name << " differs with and without the AVX2 kernels";
  }
  const JsonValue sample = parseJson(a.at("Facial-Sing.c3d.report.json"), "report");
  EXPECT_GT(member(sample, "spikes_flagged").number(""), 0.0) << "the sample's spikes went through the detector";
}

TEST(BatchCli, ResumeSkipsTakesDoneWithTheSameInputAndPreset)
{
  test::TempDir dir;
  const Archive archive(dir);
  const std::string batch = "batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("out"));
  ASSERT_EQ(mocap(batch, dir).exitCode, 0);
  const auto again = mocap(batch + " --resume", dir);
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.out.find("cleaned 0, skipped 5"), std::string::npos) << again.out;

  // A changed input is cleaned again; so is every take when the preset changes.
  fs::copy_file(test::dataFile("c3d/sample01/Eb015si.c3d"), archive.root / "session1/Eb015pi.c3d",
                fs::copy_options::overwrite_existing);
  const auto changed = mocap(batch + " --resume", dir);
  ASSERT_EQ(changed.exitCode, 0) << changed.err;
  EXPECT_NE(changed.out.find("cleaned 1, skipped 4"), std::string::npos) << changed.out;
  EXPECT_EQ(statuses(dir.file("out")).at("session1/Eb015pi.c3d"), "cleaned");
  writeFileAtomically(dir.file("preset.json"), R"({"smooth": {"method": "bspline"}})");
  const auto preset = mocap(batch + " --resume --preset " + shellQuote(dir.file("preset.json")), dir);
  ASSERT_EQ(preset.exitCode, 0) << preset.err;
  EXPECT_NE(preset.out.find("cleaned 5, skipped 0"), std::string::npos) << preset.out;
  const JsonValue report =
      parseJson(readFileBytes(dir.file("out/session2/pc_real.c3d.report.json")), "report");
  EXPECT_EQ(member(member(member(report, "preset"), "smooth"), "method").string(""), "bspline");
}

TEST(BatchCli, BadTakesAreRecordedWithTheirErrorAndTheBatchGoesOn)
{
  test::TempDir dir;
  const Archive archive(dir);
  test::writeCorruptC3d(archive.root / "session1/corrupt.c3d");
  writeFileAtomically(archive.root / "bad.txt",
                      "session1/Eb015pi.c3d\nsession1/missing.c3d\nsession1/corrupt.c3d\n\nsession1/Eb015pi.c3d\n");
  const auto run = mocap("batch " + shellQuote(archive.root / "bad.txt") + " -o " + shellQuote(dir.file("out")), dir);
  EXPECT_EQ(run.exitCode, 1) << run.err;
  EXPECT_NE(run.err.find("bad.txt:5: repeats line 1 (session1/Eb015pi.c3d); run once"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("missing.c3d"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("corrupt.c3d: parameter section corrupt"), std::string::npos) << run.err;
  const auto status = statuses(dir.file("out"));
  ASSERT_EQ(status.size(), 3u);
  EXPECT_EQ(status.at("Eb015pi.c3d"), "cleaned");
  EXPECT_EQ(status.at("missing.c3d"), "failed");
  EXPECT_EQ(status.at("corrupt.c3d"), "failed");
  EXPECT_TRUE(fs::exists(dir.file("out/Eb015pi.c3d")));
  EXPECT_FALSE(fs::exists(dir.file("out/corrupt.c3d")));  // no output for a failed take, only its report
  const JsonValue failed = parseJson(readFileBytes(dir.file("out/corrupt.c3d.report.json")), "report");
  EXPECT_EQ(member(failed, "status").string(""), "failed");
  EXPECT_NE(member(failed, "error").string("").find("parameter section corrupt"), std::string::npos);
  EXPECT_TRUE(temporaries(dir.file("out")).empty());
}

TEST(BatchCli, ATakeBelowMinValidAfterCleaningFailsTheQualityCheckWithExitThree)
{
  test::TempDir dir;
  writeFileAtomically(dir.file("list.txt"), test::sampleTake().string() + "\n");
  const auto run =
      mocap("batch " + shellQuote(dir.file("list.txt")) + " -o " + shellQuote(dir.file("out")) + " --min-valid 0.999", dir);
  EXPECT_EQ(run.exitCode, 3) << run.err;
  EXPECT_NE(run.err.find("is below --min-valid 0.999"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::exists(dir.file("out/Facial-Sing.c3d")));  // kept, flagged
  const auto pass =
      mocap("batch " + shellQuote(dir.file("list.txt")) + " -o " + shellQuote(dir.file("out")) + " --min-valid 0.5 --resume", dir);
  EXPECT_EQ(pass.exitCode, 0) << pass.err;
}

TEST(BatchCli, AnUnwritableOutDirIsOneClearErrorAndNothingRuns)
{
  test::TempDir dir;
  const Archive archive(dir);
  writeFileAtomically(dir.file("file"), "in the way");
  const auto run = mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("file") / "out"), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("cannot create the folder"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  const auto same = mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(archive.root), dir);
  EXPECT_EQ(same.exitCode, 2);
  EXPECT_NE(same.err.find("would overwrite them"), std::string::npos) << same.err;
}

// A full disk, simulated with the file size limit (ulimit -f, in 512-byte blocks in sh): writes
// past it fail with EFBIG as they would with ENOSPC. The small takes fit, the large ones do not.
TEST(BatchCli, AFullDiskFailsTheTakesThatDoNotFitAndLeavesNothingPartial)
{
  test::TempDir dir;
  const Archive archive(dir);
  const std::string command = "trap '' XFSZ; ulimit -f 400; export " + kEpoch + "; exec " + shellQuote(std::string(checkout::cliProgram())) +
                              " batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("out"));
  const auto run = test::runShell("sh -c " + shellQuote(command), dir.path());
  EXPECT_EQ(run.exitCode, 1) << run.err;
  const auto status = statuses(dir.file("out"));
  std::size_t failed = 0;
  for (const std::string& take : archive.relative) {
    const bool small = fs::file_size(archive.root / take) < 100000;
    EXPECT_EQ(status.at(take), small ? "cleaned" : "failed") << take;
    EXPECT_EQ(fs::exists(dir.file("out") / take), small) << take;
    failed += small ? 0 : 1;
  }
  EXPECT_GE(failed, 1u);
  EXPECT_NE(run.err.find("File too large"), std::string::npos) << run.err;
  EXPECT_TRUE(temporaries(dir.file("out")).empty());
}

TEST(BatchCli, AFolderManifestIsSearchedAndALinkLoopIsNotFollowed)
{
  test::TempDir dir;
  const Archive archive(dir);
  fs::create_directory_symlink(archive.root, archive.root / "session2/loop");
  const auto run = mocap("batch " + shellQuote(archive.root) + " -o " + shellQuote(dir.file("out")) + " --json", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.err.find("(a folder loop); not followed"), std::string::npos) << run.err;
  const JsonValue report = parseJson(run.out, "stdout");
  EXPECT_EQ(member(member(report, "counts"), "cleaned").number(""), 5.0);
  EXPECT_EQ(run.out, readFileBytes(dir.file("out/batch.json")));
}

TEST(BatchCli, CtrlCStopsCleanlyKeepingFinishedTakesAndResumeFinishes)
{
  test::TempDir dir;
  fs::create_directories(dir.file("many"));
  for (int i = 0; i < 40; ++i)
    fs::copy_file(test::dataFile("c3d/sample01/Eb015pr.c3d"), dir.file("many") / ("take" + std::to_string(i) + ".c3d"));
  const fs::path out = dir.file("out");
  // Start the batch, wait for its first finished take, then interrupt it.
  const std::string script = kEpoch + shellQuote(std::string(checkout::cliProgram())) + " batch " + shellQuote(dir.file("many")) +
                             " -o " + shellQuote(out) + " --jobs 2 & pid=$!; i=0; while [ $i -lt 600 ] && ! ls " +
                             shellQuote(out) + "/*.report.json >/dev/null 2>&1; do sleep 0.05; i=$((i+1)); done; " +
                             "kill -INT $pid; wait $pid; echo exit=$?";
  const auto run = test::runShell(script, dir.path());
  ASSERT_NE(run.out.find("exit=130"), std::string::npos) << run.out << run.err;
  EXPECT_NE(run.err.find("stopped;"), std::string::npos) << run.err;
  const auto status = statuses(out);
  std::size_t cleaned = 0, notRun = 0;
  for (const auto& [take, state] : status) {
    cleaned += state == "cleaned" ? 1u : 0u;
    notRun += state == "not_run" ? 1u : 0u;
    EXPECT_EQ(fs::exists(out / take), state == "cleaned") << take;
    EXPECT_EQ(fs::exists(out / (take + ".report.json")), state == "cleaned") << take;
  }
  EXPECT_GE(cleaned, 1u);
  EXPECT_GE(notRun, 1u);
  EXPECT_EQ(cleaned + notRun, 40u);
  EXPECT_TRUE(temporaries(out).empty());
  const JsonValue report = parseJson(readFileBytes(out / "batch.json"), "batch.json");
  EXPECT_TRUE(member(report, "cancelled").boolean(""));

  const auto resumed = mocap("batch " + shellQuote(dir.file("many")) + " -o " + shellQuote(out) + " --resume", dir);
  ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("cleaned " + std::to_string(notRun) + ", skipped " + std::to_string(cleaned)),
            std::string::npos)
      << resumed.out;
}

// The README's GNU parallel line, on the test takes: one `mocap clean --manifest --index` per
// take writes exactly what `mocap batch` writes.
TEST(BatchCli, GnuParallelOverManifestIndicesWritesWhatTheBatchWrites)
{
  test::TempDir dir;
  const Archive archive(dir);
  ASSERT_EQ(mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("batch")), dir).exitCode, 0);
  const std::string command = "export " + kEpoch + "; seq 0 4 | parallel --halt now,fail=1 -j 2 " +
                              shellQuote(std::string(checkout::cliProgram())) + " clean --manifest " +
                              shellQuote(archive.manifest()) + " --index {} -o " + shellQuote(dir.file("parallel"));
  const auto run = test::runShell(command, dir.path());
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  auto batch = filesBelow(dir.file("batch")), parallel = filesBelow(dir.file("parallel"));
  batch.erase("batch.json");
  ASSERT_EQ(parallel.size(), batch.size());
  for (const auto& [name, bytes] : batch)
    EXPECT_EQ(withoutTimings(parallel.at(name)), withoutTimings(bytes)) << name;
}

TEST(BatchCli, CleanManifestTakesItsIndexFromTheArrayVariables)
{
  test::TempDir dir;
  const Archive archive(dir);
  const std::string clean = "clean --manifest " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("out"));
  const auto slurm = mocap(clean, dir, kEpoch + "SLURM_ARRAY_TASK_ID=2 ");
  ASSERT_EQ(slurm.exitCode, 0) << slurm.err;
  EXPECT_TRUE(fs::exists(dir.file("out/session2/day1/dec_real.c3d")));
  const auto k8s = mocap(clean, dir, kEpoch + "JOB_COMPLETION_INDEX=4 ");
  ASSERT_EQ(k8s.exitCode, 0) << k8s.err;
  EXPECT_TRUE(fs::exists(dir.file("out/session2/TESTAPI.c3d")));
  EXPECT_FALSE(fs::exists(dir.file("out/session1")));  // only the two takes asked for were written
  EXPECT_EQ(test::entryCount(dir.file("out/session2")), 3u);  // day1/, TESTAPI.c3d and its report

  const auto outside = mocap(clean + " --index 5", dir);
  EXPECT_EQ(outside.exitCode, 2);
  EXPECT_NE(outside.err.find("--index 5: the manifest has 5 takes (0..4)"), std::string::npos) << outside.err;
  const auto none = mocap(clean, dir, "");
  EXPECT_EQ(none.exitCode, 2);
  EXPECT_NE(none.err.find("--manifest needs --index I"), std::string::npos) << none.err;
  EXPECT_EQ(mocap("clean " + shellQuote(archive.root / "session1/Eb015pi.c3d") + " --index 1 -o x.c3d", dir).exitCode, 2);
}

// A job array needs its size: `--count` prints the manifest's takes (what --index counts).
// --min-valid-after is the batch's quality check for one take: exit 3, the take kept.
TEST(BatchCli, CleanManifestCountsTheTakesAndChecksTheValidFractionAfterCleaning)
{
  test::TempDir dir;
  const Archive archive(dir);
  const auto count = mocap("clean --manifest " + shellQuote(archive.manifest()) + " --count", dir);
  ASSERT_EQ(count.exitCode, 0) << count.err;
  EXPECT_EQ(count.out, "5\n");
  EXPECT_EQ(mocap("clean --manifest " + shellQuote(archive.manifest()) + " --count --index 1", dir).exitCode, 2);
  EXPECT_EQ(mocap("clean " + shellQuote(test::sampleTake()) + " --count", dir).exitCode, 2);  // needs --manifest
  const auto noOutput = mocap("clean " + shellQuote(test::sampleTake()), dir);
  EXPECT_EQ(noOutput.exitCode, 2);
  EXPECT_NE(noOutput.err.find("-o OUT is required"), std::string::npos) << noOutput.err;

  writeFileAtomically(dir.file("list.txt"), test::sampleTake().string() + "\n");
  const std::string one = "clean --manifest " + shellQuote(dir.file("list.txt")) + " --index 0 -o " + shellQuote(dir.file("out"));
  const auto low = mocap(one + " --min-valid-after 0.999", dir);
  EXPECT_EQ(low.exitCode, 3) << low.err;
  EXPECT_NE(low.err.find("is below --min-valid-after 0.999"), std::string::npos) << low.err;
  EXPECT_TRUE(fs::exists(dir.file("out/Facial-Sing.c3d")));  // kept, flagged
  EXPECT_EQ(mocap(one + " --min-valid-after 0.5 --resume", dir).exitCode, 0);
  const auto single = mocap("clean " + shellQuote(test::sampleTake()) + " -o " + shellQuote(dir.file("one.c3d")) +
                                " --min-valid-after 0.999", dir);
  EXPECT_EQ(single.exitCode, 3) << single.err;
  EXPECT_TRUE(fs::exists(dir.file("one.c3d")));
}

TEST(BatchCli, APresetIsReadStrictlyAndReplacesTheCleaningOptions)
{
  test::TempDir dir;
  const Archive archive(dir);
  writeFileAtomically(dir.file("bad.json"), R"({"fill": {"method": "auto", "max_gap_s": 1}})");
  const auto bad = mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("out")) +
                             " --preset " + shellQuote(dir.file("bad.json")),
                         dir);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("bad.json: preset fill: unknown key 'max_gap_s'"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir.file("out")));

  // A preset a take cannot satisfy (head markers it lacks) fails that take, with the reason.
  writeFileAtomically(dir.file("head.json"), R"({"stabilize": {"markers": ["head1", "head2", "head3"]}})");
  const auto head = mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("out")) +
                              " --preset " + shellQuote(dir.file("head.json")),
                          dir);
  EXPECT_EQ(head.exitCode, 1);
  EXPECT_NE(head.err.find("Eb015pi.c3d: the take has no marker labelled 'head1'"), std::string::npos) << head.err;
  EXPECT_FALSE(fs::exists(dir.file("out/session1/Eb015pi.c3d")));
  EXPECT_EQ(statuses(dir.file("out")).at("session1/Eb015pi.c3d"), "failed");

  // The same options as a preset and as flags clean a take to the same bytes.
  writeFileAtomically(dir.file("p.json"), R"({"spikes": {"method": "off"}, "smooth": {"method": "bspline"}})");
  const std::string take = shellQuote(archive.root / "session1/Eb015pi.c3d");
  ASSERT_EQ(mocap("clean " + take + " -o " + shellQuote(dir.file("a.c3d")) + " --preset " + shellQuote(dir.file("p.json")), dir)
                .exitCode,
            0);
  ASSERT_EQ(mocap("clean " + take + " -o " + shellQuote(dir.file("b.c3d")) + " --spikes off --smooth bspline", dir).exitCode,
            0);
  EXPECT_TRUE(readFileBytes(dir.file("a.c3d")) == readFileBytes(dir.file("b.c3d")));
  const auto both = mocap("clean " + take + " -o " + shellQuote(dir.file("c.c3d")) + " --preset " +
                              shellQuote(dir.file("p.json")) + " --smooth bspline",
                          dir);
  EXPECT_EQ(both.exitCode, 2);
}

/// Whether `text` is well-formed XML (tags nest and close, attributes are quoted, '&' starts an
/// entity), with one root element named `root`; `error` says where it is not.
bool wellFormed(const std::string& text, const std::string& root, std::string& error)
{
  std::vector<std::string> open;
  std::size_t roots = 0;
  std::size_t i = 0;
  const auto fail = [&](const std::string& what) {
    error = what + " at byte " + std::to_string(i);
    return false;
  };
  while (i < text.size()) {
    if (text[i] == '&') {
      const std::size_t end = text.find(';', i);
      static const std::set<std::string> entities = {"amp", "lt", "gt", "quot", "#39"};
      if (end == std::string::npos || entities.count(text.substr(i + 1, end - i - 1)) == 0)
        return fail("a bare '&'");
      i = end + 1;
      continue;
    }
    if (text[i] != '<') {
      if (text[i] == '>')
        return fail("a bare '>'");
      ++i;
      continue;
    }
    if (text.compare(i, 9, "<!DOCTYPE") == 0) {
      i = text.find('>', i) + 1;
      continue;
    }
    const std::size_t end = text.find('>', i);
    if (end == std::string::npos)
      return fail("an unclosed tag");
    std::string tag = text.substr(i + 1, end - i - 1);
    if (!tag.empty() && tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1))
        return fail("</" + tag.substr(1) + "> closes " + (open.empty() ? std::string("nothing") : "<" + open.back() + ">"));
      open.pop_back();
      i = end + 1;
      continue;
    }
    const bool selfClosing = !tag.empty() && tag.back() == '/';
    if (selfClosing)
      tag.pop_back();
    const std::size_t nameEnd = std::min(tag.find(' '), tag.size());
    const std::string name = tag.substr(0, nameEnd);
    // Attributes: name="value" pairs.
    for (std::size_t a = nameEnd; a < tag.size();) {
      if (tag[a] == ' ') {
        ++a;
        continue;
      }
      const std::size_t eq = tag.find('=', a);
      if (eq == std::string::npos || eq + 1 >= tag.size() || tag[eq + 1] != '"')
        return fail("an unquoted attribute in <" + name + ">");
      const std::size_t close = tag.find('"', eq + 2);
      if (close == std::string::npos)
        return fail("an unclosed attribute in <" + name + ">");
      a = close + 1;
    }
    if (open.empty())
      ++roots;
    if (open.empty() && name != root)
      return fail("root <" + name + ">");
    if (!selfClosing)
      open.push_back(name);
    i = end + 1;
  }
  if (!open.empty())
    return fail("<" + open.back() + "> never closed");
  if (roots != 1)
    return fail(std::to_string(roots) + " root elements");
  return true;
}

std::size_t occurrences(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

TEST(SummarizeCli, WritesOneWellFormedPageWithThePlotsAndTheTakesToReview)
{
  test::TempDir dir;
  const Archive archive(dir);
  test::writeCorruptC3d(archive.root / "session1/corrupt.c3d");
  writeFileAtomically(archive.manifest(), readFileBytes(archive.manifest()) + "session1/corrupt.c3d\n");
  ASSERT_EQ(mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("out")), dir).exitCode, 1);
  const auto run =
      mocap("summarize " + shellQuote(dir.file("out")) + " -o " + shellQuote(dir.file("report.html")) + " --json", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string html = readFileBytes(dir.file("report.html"));
  std::string error;
  EXPECT_TRUE(wellFormed(html, "html", error)) << error;
  EXPECT_EQ(html.find("http://www.w3.org/1999/xhtml"), html.find("http"));  // no link but the namespaces
  EXPECT_EQ(html.find("<script"), std::string::npos);
  for (const std::string id : {"valid-fraction", "gap-lengths", "spikes-per-marker", "missing-heat-map"})
    EXPECT_NE(html.find("<svg class=\"plot\" id=\"" + id + "\""), std::string::npos) << id;
  EXPECT_EQ(occurrences(html, "<g class=\"take\""), 5u);  // the five cleaned takes, before and after
  EXPECT_EQ(occurrences(html, "<g class=\"failed\""), 1u);  // a cross on the axis, not a full-height bar
  EXPECT_EQ(occurrences(html, "<rect class=\"failed\""), 0u);
  EXPECT_GT(occurrences(html, "<rect class=\"cell\""), 5u);
  EXPECT_EQ(occurrences(html, "<rect class=\"bar\" data-label=\"1\" data-count=\""), 1u);

  const JsonValue summary = parseJson(run.out, "stdout");
  EXPECT_EQ(member(summary, "takes").number(""), 6.0);
  EXPECT_EQ(member(summary, "failed").number(""), 1.0);
  const auto& review = member(summary, "review").array("");
  ASSERT_FALSE(review.empty());
  EXPECT_EQ(member(review.front(), "take").string(""), "session1/corrupt.c3d");  // worst first
  EXPECT_NE(member(review.front(), "reason").string("").find("failed: "), std::string::npos);
  // Every gap of the reports is in the histogram.
  double gaps = 0, histogram = 0;
  for (const auto& [name, bytes] : filesBelow(dir.file("out")))
    if (name.size() > 12 && name.substr(name.size() - 12) == ".report.json") {
      const JsonValue report = parseJson(bytes, name);
      if (const JsonValue* markers = report.find("markers", name))
        for (const JsonValue& marker : markers->array(""))
          gaps += static_cast<double>(member(marker, "gap_lengths").array("").size());
    }
  for (const JsonValue& bin : member(summary, "gap_length_histogram").array(""))
    histogram += member(bin, "gaps").number("");
  EXPECT_EQ(histogram, gaps);
  EXPECT_GT(gaps, 0.0);
}

/// `mocap batch` of the archive's manifest into dir/out (some takes may fail), then `mocap
/// summarize` of it into dir/report.html: the summary's JSON (its text in `out`).
JsonValue cleanAndSummarize(const Archive& archive, const test::TempDir& dir, std::string& out)
{
  const auto batch = mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("out")), dir);
  EXPECT_LE(batch.exitCode, 3) << batch.err;
  const auto run =
      mocap("summarize " + shellQuote(dir.file("out")) + " -o " + shellQuote(dir.file("report.html")) + " --json", dir);
  EXPECT_EQ(run.exitCode, 0) << run.err;
  out = run.out;
  return parseJson(run.out, "stdout");
}

TEST(SummarizeCli, ATakeThatLostDataOnReadingIsListedFirstWithWhy)
{
  test::TempDir dir;
  const Archive archive(dir);
  // A truncated copy: the reader keeps the whole frames and says data is missing.
  const std::string bytes = readFileBytes(archive.root / "session2/pc_real.c3d");
  writeFileAtomically(archive.root / "session2/cut.c3d", bytes.substr(0, bytes.size() - 5000));
  writeFileAtomically(archive.manifest(), readFileBytes(archive.manifest()) + "session2/cut.c3d\n");
  std::string out;
  const JsonValue summary = cleanAndSummarize(archive, dir, out);
  const auto& review = member(summary, "review").array("");
  ASSERT_FALSE(review.empty());
  EXPECT_EQ(member(review.front(), "take").string(""), "session2/cut.c3d")
      << "data loss before takes that only have open gaps; " << out.substr(0, 2000);
  EXPECT_NE(member(review.front(), "reason").string("").find("data lost on reading: "), std::string::npos);
  EXPECT_NE(member(review.front(), "reason").string("").find("shorter than declared"), std::string::npos);
  EXPECT_TRUE(member(review.front(), "data_loss").boolean(""));
  EXPECT_GE(member(review.front(), "warnings").number(""), 1.0);
  const std::string html = readFileBytes(dir.file("report.html"));
  EXPECT_NE(html.find("<th>reader warnings</th>"), std::string::npos);
  EXPECT_NE(html.find("<tr class=\"bad\"><td>session2/cut.c3d</td>"), std::string::npos);
}

TEST(SummarizeCli, AnAcknowledgedDataLossIsNoLongerATakeThatNeedsAPerson)
{
  // The truncated take read and saved twice: once as it was read (the finding carried in its
  // history), once after a person acknowledged the finding. Only the first needs a person for it.
  test::TempDir dir;
  const Archive archive(dir);
  const std::string bytes = readFileBytes(archive.root / "session2/pc_real.c3d");
  writeFileAtomically(dir.file("cut.c3d"), bytes.substr(0, bytes.size() - 5000));
  Take take = readTake(dir.file("cut.c3d"));
  writeTake(take, archive.root / "session2/carried.c3d");
  const std::vector<DataLossRecord> records = dataLossRecords(take);
  ASSERT_EQ(records.size(), 1u);
  take.history().push_back(acknowledgementOf(records.front(), "test", "2026-12-06T17:00:00Z"));
  writeTake(take, archive.root / "session2/acknowledged.c3d");
  // Wrapped integer coordinates: data that is there but wrong, said so.
  fs::copy_file(test::dataFile("c3d/sample37/ART-Human_tools_integer_6dofLimbs.c3d"), archive.root / "session2/art.c3d");
  writeFileAtomically(archive.manifest(), readFileBytes(archive.manifest()) +
                                              "session2/carried.c3d\nsession2/acknowledged.c3d\nsession2/art.c3d\n");
  std::string out;
  const JsonValue summary = cleanAndSummarize(archive, dir, out);
  std::map<std::string, const JsonValue*> review;
  for (const JsonValue& entry : member(summary, "review").array(""))
    review[member(entry, "take").string("")] = &entry;
  ASSERT_EQ(review.count("session2/carried.c3d"), 1u) << out.substr(0, 2000);
  EXPECT_TRUE(member(*review["session2/carried.c3d"], "data_loss").boolean(""));
  EXPECT_NE(member(*review["session2/carried.c3d"], "reason").string("").find("recorded when cut.c3d was read"),
            std::string::npos);
  EXPECT_EQ(member(*review["session2/carried.c3d"], "reason").string("").rfind("data lost on reading: ", 0), 0u);
  ASSERT_EQ(review.count("session2/art.c3d"), 1u);
  EXPECT_EQ(member(*review["session2/art.c3d"], "reason").string("").rfind("wrong data on reading: ", 0), 0u)
      << member(*review["session2/art.c3d"], "reason").string("");
  if (review.count("session2/acknowledged.c3d")) {  // listed only for other reasons (its open gaps)
    const JsonValue& acknowledged = *review["session2/acknowledged.c3d"];
    EXPECT_FALSE(member(acknowledged, "data_loss").boolean(""));
    EXPECT_EQ(member(acknowledged, "reason").string("").find("data lost"), std::string::npos)
        << member(acknowledged, "reason").string("");
  }
}

TEST(SummarizeCli, GroupsFailuresByReasonWhileTheOtherTakesStillRun)
{
  test::TempDir dir;
  const Archive archive(dir);
  // One take names the preset's head markers; the five others lack them.
  Take headed = readTake(archive.root / "session1/Eb015pi.c3d");
  for (Eigen::Index m = 0; m < 3; ++m)
    headed.setLabel(m, "head" + std::to_string(m + 1));
  writeTake(headed, archive.root / "session1/headed.c3d");
  writeFileAtomically(archive.manifest(), readFileBytes(archive.manifest()) + "session1/headed.c3d\n");
  writeFileAtomically(dir.file("head.json"), R"({"stabilize": {"markers": ["head1", "head2", "head3"]}})");
  const auto batch = mocap("batch " + shellQuote(archive.manifest()) + " -o " + shellQuote(dir.file("out")) +
                               " --preset " + shellQuote(dir.file("head.json")),
                           dir);
  EXPECT_EQ(batch.exitCode, 1) << batch.err;
  const auto status = statuses(dir.file("out"));
  EXPECT_EQ(status.at("session1/headed.c3d"), "cleaned") << "a take that has them runs";
  EXPECT_EQ(std::count_if(status.begin(), status.end(), [](const auto& s) { return s.second == "failed"; }), 5);

  const auto run =
      mocap("summarize " + shellQuote(dir.file("out")) + " -o " + shellQuote(dir.file("report.html")) + " --json", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const JsonValue summary = parseJson(run.out, "stdout");
  const auto& groups = member(summary, "failures_by_reason").array("");
  ASSERT_EQ(groups.size(), 1u) << run.out;
  EXPECT_NE(member(groups.front(), "reason").string("").find("no marker labelled 'head1'"), std::string::npos)
      << member(groups.front(), "reason").string("");
  EXPECT_EQ(member(groups.front(), "takes").array("").size(), 5u);
  const std::string html = readFileBytes(dir.file("report.html"));
  EXPECT_NE(html.find("<table id=\"failures\">"), std::string::npos);
  std::string error;
  EXPECT_TRUE(wellFormed(html, "html", error)) << error;
}

} // namespace
} // namespace mocap
