// The `mocap` executable end to end: exit codes, one-line errors, JSON output, no partial files.
#include "../core/test_support.h"

#include "mocap/file_io.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sys/wait.h>

namespace mocap {
namespace {

struct CommandResult
{
  int exitCode = -1;
  std::string out;
  std::string err;
};

std::string shellQuote(const std::string& s)
{
  std::string q = "'";
  for (char c : s)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

CommandResult runMocap(const std::string& arguments, const test::TempDir& dir)
{
  const auto errFile = dir.file("stderr.txt");
  const std::string command = shellQuote(MOCAP_CLI) + " " + arguments + " 2>" + shellQuote(errFile.string());
  CommandResult run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
    return run;
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    run.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = readFileBytes(errFile);
  std::filesystem::remove(errFile);
  return run;
}

std::string q(const std::filesystem::path& p)
{
  return shellQuote(p.string());
}

TEST(Cli, InfoJsonListsTheTakeAndEveryGap)
{
  test::TempDir dir;
  const CommandResult run = runMocap("info " + q(test::sampleTake()) + " --json", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("\"frames\": 3000"), std::string::npos);
  EXPECT_NE(run.out.find("\"marker_count\": 38"), std::string::npos);
  EXPECT_NE(run.out.find("\"frame_rate\": 100"), std::string::npos);
  EXPECT_NE(run.out.find("\"units\": \"mm\""), std::string::npos);
  EXPECT_NE(run.out.find("\"marker\": \"section3-1\",\n      \"first_frame\": 887,\n      \"length\": 33"),
            std::string::npos)
      << run.out.substr(0, 2000);
  EXPECT_NE(run.out.find("\"marker\": \"section6-1\",\n      \"first_frame\": 1935,\n      \"length\": 192"),
            std::string::npos);
}

TEST(Cli, InfoTextSaysValidFraction)
{
  test::TempDir dir;
  const CommandResult run = runMocap("info " + q(test::sampleTake()), dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("frames:          3000"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("valid samples:   96."), std::string::npos) << run.out;
}

TEST(Cli, CorruptFileGivesExitOneAndOneClearLine)
{
  test::TempDir dir;
  const CommandResult run = runMocap("info " + q(test::dataFile("c3d/sample18/bad_parameter_section.c3d")), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_NE(run.err.find("bad_parameter_section.c3d: parameter section corrupt"), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty());
}

TEST(Cli, BadUsageGivesExitTwo)
{
  test::TempDir dir;
  EXPECT_EQ(runMocap("", dir).exitCode, 2);
  EXPECT_EQ(runMocap("frobnicate x", dir).exitCode, 2);
  EXPECT_EQ(runMocap("info", dir).exitCode, 2);
  EXPECT_EQ(runMocap("info " + q(test::sampleTake()) + " --bogus", dir).exitCode, 2);
  EXPECT_EQ(runMocap("convert " + q(test::sampleTake()) + " " + q(dir.file("x.xyz")), dir).exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.xyz")));
  EXPECT_EQ(runMocap("--help", dir).exitCode, 0);
}

TEST(Cli, ConvertWritesEveryFormatAndTrcReadsBack)
{
  test::TempDir dir;
  for (const char* name : {"take.trc", "take.csv", "take.bvh", "take.c3d"}) {
    const CommandResult run = runMocap("convert " + q(test::sampleTake()) + " " + q(dir.file(name)), dir);
    ASSERT_EQ(run.exitCode, 0) << name << ": " << run.err;
    EXPECT_GT(std::filesystem::file_size(dir.file(name)), 1000u) << name;
  }
  const CommandResult info = runMocap("info " + q(dir.file("take.trc")) + " --json", dir);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_NE(info.out.find("\"frames\": 3000"), std::string::npos);
  EXPECT_NE(info.out.find("\"first_frame\": 887,\n      \"length\": 33"), std::string::npos);
  EXPECT_EQ(readFileBytes(dir.file("take.csv")).rfind("Frame,Time,root-1:X,root-1:Y,root-1:Z,", 0), 0u);
}

TEST(Cli, ConvertRescalesUnitsOnRequest)
{
  test::TempDir dir;
  const CommandResult run =
      runMocap("convert " + q(test::sampleTake()) + " " + q(dir.file("metres.c3d")) + " --units m", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const CommandResult info = runMocap("info " + q(dir.file("metres.c3d")) + " --json", dir);
  EXPECT_NE(info.out.find("\"units\": \"m\""), std::string::npos) << info.out.substr(0, 400);
  EXPECT_EQ(runMocap("convert " + q(test::sampleTake()) + " " + q(dir.file("x.c3d")) + " --units furlong", dir).exitCode, 2);
  EXPECT_EQ(runMocap("convert " + q(test::sampleTake()) + " " + q(dir.file("x.c3d")) + " --units", dir).exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.c3d")));
}

TEST(Cli, EvaluationAndPlanningCommandsPrintJson)
{
  test::TempDir dir;
  const std::string nose = q(test::dataFile("trc/NoseMoCap.trc"));
  const CommandResult spikes = runMocap("eval-spikes " + nose + " --count 50 --json", dir);
  ASSERT_EQ(spikes.exitCode, 0) << spikes.err;
  EXPECT_NE(spikes.out.find("\"method\": \"robust\""), std::string::npos) << spikes.out.substr(0, 400);
  EXPECT_NE(spikes.out.find("\"recall\""), std::string::npos);
  const CommandResult smooth = runMocap("eval-smooth " + nose + " --noise 0.5 --json", dir);
  ASSERT_EQ(smooth.exitCode, 0) << smooth.err;
  EXPECT_NE(smooth.out.find("\"acceleration_rmse\""), std::string::npos);
  const CommandResult table = runMocap("smooth-table " + nose + " --json", dir);
  ASSERT_EQ(table.exitCode, 0) << table.err;
  EXPECT_NE(table.out.find("\"smoothness\""), std::string::npos);
  const CommandResult pfa =
      runMocap("pfa " + nose + " --restarts 20 --k 5:7 --json --curve " + q(dir.file("curve.csv")), dir);
  ASSERT_EQ(pfa.exitCode, 0) << pfa.err;
  EXPECT_NE(pfa.out.find("\"recommended\""), std::string::npos);
  EXPECT_GT(std::filesystem::file_size(dir.file("curve.csv")), 50u);
  EXPECT_EQ(runMocap("pfa " + nose + " --k 9:3", dir).exitCode, 2);
  EXPECT_EQ(runMocap("eval-spikes " + nose + " --amplitude -5", dir).exitCode, 2);
  EXPECT_EQ(runMocap("eval-smooth " + q(dir.file("missing.trc")), dir).exitCode, 1);
}

TEST(Cli, CleanFillsTheSampleAndReportsEveryStep)
{
  test::TempDir dir;
  const CommandResult run = runMocap("clean " + q(test::sampleTake()) + " -o " + q(dir.file("clean.c3d")) +
                                         " --stabilize root-1,root-2,root-3,root-4,root-5,root-6 --smooth bspline"
                                         " --max-gap 200 --report " + q(dir.file("report.json")),
                                     dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string report = readFileBytes(dir.file("report.json"));
  for (const char* key : {"\"spikes\"", "\"fill\"", "\"smooth\"", "\"gaps\"", "\"flagged\"", "\"filled_gaps\""})
    EXPECT_NE(report.find(key), std::string::npos) << key;
  // Interior gaps up to 200 frames are filled; the stray Unlabeled1 (35 valid frames) is not.
  EXPECT_NE(report.find("\"marker\": \"section6-1\",\n        \"first_frame\": 1935,\n        \"length\": 192,\n"
                        "        \"filled\": true"),
            std::string::npos)
      << report.substr(0, 3000);
  const CommandResult info = runMocap("info " + q(dir.file("clean.c3d")) + " --json", dir);
  ASSERT_EQ(info.exitCode, 0);
  EXPECT_EQ(info.out.find("\"marker\": \"section3-1\""), std::string::npos) << "section3-1's gap was filled";
  EXPECT_EQ(runMocap("clean " + q(test::sampleTake()), dir).exitCode, 2) << "-o is required";
  EXPECT_EQ(runMocap("clean " + q(test::sampleTake()) + " -o " + q(dir.file("x.c3d")) + " --fill magic", dir).exitCode, 2);
  EXPECT_EQ(runMocap("clean " + q(test::sampleTake()) + " -o " + q(dir.file("x.c3d")) + " --stabilize nope", dir).exitCode,
            2);
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.c3d")));
}

TEST(Cli, FailedConvertLeavesNoOutputFile)
{
  test::TempDir dir;
  const std::string bytes = readFileBytes(test::dataFile("c3d/sample01/Eb015pi.c3d"));
  writeFileAtomically(dir.file("cut.c3d"), bytes.substr(0, 1500));
  const CommandResult run = runMocap("convert " + q(dir.file("cut.c3d")) + " " + q(dir.file("out.trc")), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("parameter section truncated at byte"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.trc")));
  const CommandResult same = runMocap("convert " + q(dir.file("cut.c3d")) + " " + q(dir.file("cut.c3d")), dir);
  EXPECT_EQ(same.exitCode, 2);
  EXPECT_EQ(readFileBytes(dir.file("cut.c3d")).size(), 1500u);
}

} // namespace
} // namespace mocap
