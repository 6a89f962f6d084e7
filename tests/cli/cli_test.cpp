// The `mocap` executable end to end: exit codes, one-line errors, JSON output, no partial files.
#include "../core/fbx_test_reader.h"
#include "../core/test_support.h"
#include "foreign_takes.h"

#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/model/data_loss_record.h"
#include "mocap/model/marker_points.h"
#include "mocap/io/marker_set_io.h"
#include "mocap/io/take_io.h"
#include "mocap/model/provenance.h"
#include "mocap/evaluation/tracking_evaluation.h"
#include "checkout_paths.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include <algorithm>
#include <array>
#include <map>
#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <utility>
#include <vector>

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
  const std::string command = shellQuote(checkout::cliProgram()) + " " + arguments + " 2>" + shellQuote(errFile.string());
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

// totals.origin.<name> of a `mocap info --json` document.
double originTotal(const JsonValue& info, const std::string& name)
{
  return info.find("totals", "info")->find("origin", "totals")->find(name, "origin")->number(name);
}

// The samples of the history step named `operation` (the last one).
double historySamples(const JsonValue& info, const std::string& operation)
{
  double samples = -1.0;
  for (const JsonValue& step : info.find("history", "info")->array("history"))
    if (step.find("operation", "step")->string("operation") == operation)
      samples = step.find("samples", "step")->number("samples");
  return samples;
}

TEST(Cli, DefaultCleanThenInfoCountsTheRepairedAndFilledSamplesTheHistoryGives)
{
  // The default clean smooths after repairing and filling; the invented samples must still count as
  // edited and filled (they used to read 0 and 0, passing for smoothed measurements).
  test::TempDir dir;
  const CommandResult before = runMocap("info " + q(test::sampleTake()) + " --json", dir);
  ASSERT_EQ(before.exitCode, 0) << before.err;
  const CommandResult clean = runMocap("clean " + q(test::sampleTake()) + " -o " + q(dir.file("clean.c3d")), dir);
  ASSERT_EQ(clean.exitCode, 0) << clean.err;
  const CommandResult after = runMocap("info " + q(dir.file("clean.c3d")) + " --json", dir);
  ASSERT_EQ(after.exitCode, 0) << after.err;
  const JsonValue input = parseJson(before.out, "info before");
  const JsonValue output = parseJson(after.out, "info after");
  const double repaired = historySamples(output, "repair spikes");
  const double filled = historySamples(output, "fill gaps");
  ASSERT_GT(repaired, 0.0);
  ASSERT_GT(filled, 0.0);
  EXPECT_EQ(originTotal(output, "edited") - originTotal(input, "edited"), repaired);
  EXPECT_EQ(originTotal(output, "filled") - originTotal(input, "filled"), filled);
  const JsonValue& operations = *output.find("totals", "info")->find("operations", "totals");
  EXPECT_EQ(operations.find("smoothed", "operations")->number("smoothed"), historySamples(output, "smooth"));
  // The version-1 keys stay: per marker and in the totals, "filled" is the filled origin.
  double markerFilled = 0.0;
  for (const JsonValue& marker : output.find("markers", "info")->array("markers"))
    markerFilled += marker.find("filled", "marker")->number("filled");
  EXPECT_EQ(markerFilled, originTotal(output, "filled"));
  EXPECT_EQ(output.find("totals", "info")->find("filled", "totals")->number("filled"), originTotal(output, "filled"));
}

TEST(Cli, InfoJsonReportsProvenanceAndDataLoss)
{
  test::TempDir dir;
  Take take = readTake(test::sampleTake());
  const Eigen::Index marker = *take.markerIndex("section3-1");
  for (Eigen::Index f = 10; f < 14; ++f)
    take.setState(f, marker, SampleState().with(SampleOperation::Smoothed));
  ProcessingStep step;
  step.operation = "smooth";
  step.parameters = {{"method", "gcvspl"}};
  step.time = "2026-12-01T20:00:00Z";
  step.tool = "test";
  take.history().push_back(step);
  writeTake(take, dir.file("processed.c3d"));
  const CommandResult run = runMocap("info " + q(dir.file("processed.c3d")) + " --json", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("\"label\": \"section3-1\",\n      \"valid_fraction\""), std::string::npos);
  EXPECT_NE(run.out.find("\"smoothed\": 4"), std::string::npos) << run.out.substr(0, 3000);
  EXPECT_NE(run.out.find("\"operation\": \"smooth\""), std::string::npos);
  EXPECT_NE(run.out.find("\"method\": \"gcvspl\""), std::string::npos);
  EXPECT_NE(run.out.find("\"data_loss\": []"), std::string::npos);

  // mocap clean appends its steps to the history the take already has.
  const CommandResult clean =
      runMocap("clean " + q(dir.file("processed.c3d")) + " -o " + q(dir.file("cleaned.c3d")), dir);
  ASSERT_EQ(clean.exitCode, 0) << clean.err;
  const Take cleaned = readTake(dir.file("cleaned.c3d"));
  ASSERT_GE(cleaned.history().size(), 3u);
  EXPECT_EQ(cleaned.history().front().operation, "smooth");
  EXPECT_EQ(cleaned.history()[1].tool, "mocap clean");
  EXPECT_EQ(cleaned.history()[2].operation, "fill gaps");

  const std::string bytes = readFileBytes(test::sampleTake());
  writeFileAtomically(dir.file("cut.c3d"), std::string_view(bytes).substr(0, bytes.size() / 2));
  const CommandResult cut = runMocap("info " + q(dir.file("cut.c3d")) + " --json", dir);
  ASSERT_EQ(cut.exitCode, 0) << cut.err;
  const auto lossAt = cut.out.find("\"data_loss\": [");
  ASSERT_NE(lossAt, std::string::npos);
  EXPECT_NE(cut.out.find("truncated", lossAt), std::string::npos) << cut.out.substr(lossAt);
}

// Data-loss findings (issue 30): info lists each with its kind; one a person acknowledged is still
// listed, as acknowledged, and is no longer a warning.
TEST(Cli, InfoListsDataLossWithItsKindAndWhetherItWasAcknowledged)
{
  test::TempDir dir;
  std::vector<std::string> found;
  Take take = readTake(test::dataFile("c3d/sample37/ART-Human_tools_integer_6dofLimbs.c3d"), nullptr, &found);
  ASSERT_EQ(found.size(), 1u);
  writeTake(take, dir.file("carried.c3d"));
  const std::vector<DataLossRecord> records = dataLossRecords(take);
  ASSERT_EQ(records.size(), 1u);
  take.history().push_back(acknowledgementOf(records.front(), "test", "2026-12-06T17:00:00Z"));
  writeTake(take, dir.file("acknowledged.c3d"));
  for (const bool acknowledged : {false, true}) {
    const std::string name = acknowledged ? "acknowledged.c3d" : "carried.c3d";
    const CommandResult info = runMocap("info " + q(dir.file(name)) + " --json", dir);
    ASSERT_EQ(info.exitCode, 0) << info.err;
    const JsonValue json = parseJson(info.out, "info");
    const auto& raised = json.find("data_loss", "info")->array("data_loss");
    ASSERT_EQ(raised.size(), acknowledged ? 0u : 1u) << "text, as scripts read it: " << name;
    if (!acknowledged) {
      EXPECT_EQ(raised.front().string("data_loss"),
                "recorded when ART-Human_tools_integer_6dofLimbs.c3d was read: " + found.front());
    }
    const auto& lost = json.find("data_loss_findings", "info")->array("data_loss_findings");
    ASSERT_EQ(lost.size(), 1u) << name;
    const JsonValue& entry = lost.front();
    EXPECT_EQ(entry.find("finding", "entry")->string("finding"),
              "recorded when ART-Human_tools_integer_6dofLimbs.c3d was read: " + found.front());
    EXPECT_EQ(entry.find("kind", "entry")->string("kind"), "wrong") << name;
    EXPECT_EQ(entry.find("acknowledged", "entry")->boolean("acknowledged"), acknowledged) << name;
    bool warned = false;
    for (const JsonValue& warning : json.find("warnings", "info")->array("warnings"))
      warned = warned || warning.string("warning").rfind("recorded when ", 0) == 0;
    EXPECT_EQ(warned, !acknowledged) << name;
  }
}

// A Nexus-style file (issue 30): info counts its point types and says how the file was laid out;
// clean leaves the model outputs as they were and says so.
TEST(Cli, ModelOutputsAreCountedAndLeftUntouched)
{
  test::TempDir dir;
  writeTake(test::nexusCleaningTake(), dir.file("nexus.c3d"));
  const CommandResult info = runMocap("info " + q(dir.file("nexus.c3d")) + " --json", dir);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  const JsonValue json = parseJson(info.out, "info");
  const JsonValue* types = json.find("point_types", "info");
  ASSERT_NE(types, nullptr) << info.out.substr(0, 500);
  const std::map<std::string, double> expected = {{"marker", 4}, {"angle", 2}, {"force", 1}, {"moment", 1},
                                                   {"power", 1}, {"other", 0}, {"virtual", 0}};
  for (const auto& [type, count] : expected) {
    const JsonValue* value = types->find(type, "point_types");
    ASSERT_NE(value, nullptr) << type;
    EXPECT_EQ(value->number(type), count) << type;
  }
  const JsonValue* layout = json.find("layout", "info");
  ASSERT_NE(layout, nullptr);
  ASSERT_TRUE(layout->isObject());
  EXPECT_EQ(layout->find("storage", "layout")->string("storage"), "float");
  EXPECT_EQ(json.find("gap_count", "info")->number("gap_count"), 4) << "the outputs' gaps are not the take's";
  const CommandResult text = runMocap("info " + q(dir.file("nexus.c3d")), dir);
  EXPECT_NE(text.out.find("5 model outputs (2 angles, 1 force, 1 moment, 1 power)"), std::string::npos) << text.out;

  const CommandResult clean = runMocap("clean " + q(dir.file("nexus.c3d")) + " -o " + q(dir.file("cleaned.c3d")) +
                                           " --report " + q(dir.file("report.json")),
                                       dir);
  ASSERT_EQ(clean.exitCode, 0) << clean.err;
  EXPECT_NE(clean.err.find("5 model outputs (2 angles, 1 force, 1 moment, 1 power) left untouched"),
            std::string::npos)
      << clean.err;
  const JsonValue report = parseJson(readFileBytes(dir.file("report.json")), "report");
  const JsonValue* outputs = report.find("model_outputs", "report");
  ASSERT_NE(outputs, nullptr);
  EXPECT_EQ(outputs->find("untouched", "model_outputs")->number("untouched"), 5);
  const Take before = readTake(dir.file("nexus.c3d"));
  const Take after = readTake(dir.file("cleaned.c3d"));
  ASSERT_EQ(modelOutputPoints(after), modelOutputPoints(before));
  for (const Eigen::Index m : modelOutputPoints(before)) {
    EXPECT_TRUE(before.trajectory(m) == after.trajectory(m)) << before.label(m);
    EXPECT_TRUE((before.valid().col(m) == after.valid().col(m)).all()) << before.label(m);
    EXPECT_TRUE((before.states().col(m) == after.states().col(m)).all()) << before.label(m);
  }

  // A marker-only format drops the outputs, and says so.
  const CommandResult trc = runMocap("convert " + q(dir.file("nexus.c3d")) + " " + q(dir.file("nexus.trc")), dir);
  ASSERT_EQ(trc.exitCode, 0) << trc.err;
  EXPECT_NE(trc.err.find("nexus.trc: note: the TRC file holds marker positions only: 5 model outputs"),
            std::string::npos)
      << trc.err;
  const CommandResult c3d = runMocap("convert " + q(dir.file("nexus.c3d")) + " " + q(dir.file("copy.c3d")), dir);
  EXPECT_EQ(c3d.err.find("note:"), std::string::npos) << c3d.err;
}

// Vicon's gait-pig (issue 30): Plug-in Gait's 36 segment points are counted as virtual model
// outputs, left out of the gaps and untouched by clean, and the cleaned file keeps their type.
TEST(Cli, PlugInGaitVirtualPointsKeepTheirTypeThroughClean)
{
  test::TempDir dir;
  const auto pointTypes = [&dir](const std::string& file) {
    const CommandResult info = runMocap("info " + q(file) + " --json", dir);
    EXPECT_EQ(info.exitCode, 0) << info.err;
    const JsonValue json = parseJson(info.out, "info");
    std::map<std::string, double> counts;
    for (const char* type : {"marker", "angle", "virtual"})
      counts[type] = json.find("point_types", "info")->find(type, "point_types")->number(type);
    const bool guessed = info.out.find("Vicon Plug-in Gait virtual points") != std::string::npos;
    return std::make_pair(counts, guessed);
  };
  const std::string gait = test::dataFile("c3d/sample03/gait-pig-nz.c3d");
  const std::map<std::string, double> expected = {{"marker", 15}, {"angle", 12}, {"virtual", 36}};
  EXPECT_EQ(pointTypes(gait), std::make_pair(expected, true)) << "typed by the reader, which says so";
  const CommandResult clean = runMocap("clean " + q(gait) + " -o " + q(dir.file("cleaned.c3d")), dir);
  ASSERT_EQ(clean.exitCode, 0) << clean.err;
  EXPECT_NE(clean.err.find("70 model outputs (12 angles, 8 forces, 8 moments, 6 powers, 36 virtual points) left "
                           "untouched"),
            std::string::npos)
      << clean.err;
  EXPECT_EQ(pointTypes(dir.file("cleaned.c3d")), std::make_pair(expected, false)) << "listed in the written file";
  const Take before = readTake(gait);
  const Take after = readTake(dir.file("cleaned.c3d"));
  const Eigen::Index pelvis = *before.markerIndex("PELO");
  EXPECT_TRUE(before.trajectory(pelvis) == after.trajectory(pelvis)) << "never cleaned";
}

TEST(Cli, CorruptFileGivesExitOneAndOneClearLine)
{
  test::TempDir dir;
  test::writeCorruptC3d(dir.file("corrupt.c3d"));
  const CommandResult run = runMocap("info " + q(dir.file("corrupt.c3d")), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_NE(run.err.find("corrupt.c3d: parameter section corrupt"), std::string::npos) << run.err;
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

const std::vector<std::string> kCommands = {"info",         "convert", "clean", "eval-fill", "eval-spikes",
                                            "eval-smooth",  "smooth-table", "pfa", "track", "fix-swaps",
                                            "eval-track",   "bind",    "deform"};

std::vector<std::string> lines(const std::string& text)
{
  std::vector<std::string> result;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    result.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  return result;
}

// The lines that differ between `expected` and `actual` (a longest-common-subsequence diff):
// "-N text" only in expected, "+N text" only in actual, N the line number.
std::string lineDiff(const std::string& expected, const std::string& actual)
{
  const std::vector<std::string> a = lines(expected), b = lines(actual);
  std::vector<std::vector<std::size_t>> common(a.size() + 1, std::vector<std::size_t>(b.size() + 1, 0));
  for (std::size_t i = a.size(); i-- > 0;)
    for (std::size_t j = b.size(); j-- > 0;)
      common[i][j] = a[i] == b[j] ? common[i + 1][j + 1] + 1 : std::max(common[i + 1][j], common[i][j + 1]);
  std::string diff;
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (i < a.size() && j < b.size() && a[i] == b[j]) {
      ++i;
      ++j;
    } else if (j < b.size() && (i == a.size() || common[i][j + 1] > common[i + 1][j])) {
      diff += "+" + std::to_string(j + 1) + " " + b[j] + "\n";
      ++j;
    } else {
      diff += "-" + std::to_string(i + 1) + " " + a[i] + "\n";
      ++i;
    }
  }
  return diff;
}

// `command`'s entry in `mocap --help`: its synopsis lines, without the description.
std::string listedSynopsis(const std::string& help, const std::string& command)
{
  std::string synopsis;
  bool inside = false;
  for (const std::string& line : lines(help)) {
    const bool starts = line.size() > 2 && line.rfind("  ", 0) == 0 && line[2] != ' ';
    const bool continues = line.size() > 6 && line.rfind("      ", 0) == 0 && line[6] != ' ';
    if (starts)
      inside = line.rfind("  " + command + " ", 0) == 0;
    else if (!continues)
      inside = false;
    if (inside)
      synopsis += line + "\n";
  }
  return synopsis;
}

// Every command answers --help and -h with its own usage, generated from its definition: the
// synopsis `mocap --help` lists for it, its description and its options; a usage error shows the
// command's short usage and where to read more, not every command's.
TEST(Cli, EveryCommandAnswersHelpWithItsOwnUsage)
{
  test::TempDir dir;
  const CommandResult all = runMocap("--help", dir);
  ASSERT_EQ(all.exitCode, 0);
  for (const std::string& command : kCommands) {
    const CommandResult help = runMocap(command + " --help", dir);
    EXPECT_EQ(help.exitCode, 0) << command;
    EXPECT_EQ(help.out.rfind("usage: mocap " + command + " ", 0), 0u) << help.out;
    EXPECT_EQ(help.out.find("commands:"), std::string::npos) << command;
    EXPECT_NE(help.out.find("Options:"), std::string::npos) << help.out;
    const std::string listed = listedSynopsis(all.out, command);
    ASSERT_FALSE(listed.empty()) << command << " missing in mocap --help:\n" << all.out;
    const std::string usage = "usage: mocap " + listed.substr(2);
    EXPECT_EQ(help.out.substr(0, usage.size()), usage) << command;
    EXPECT_EQ(runMocap(command + " -h", dir).out, help.out) << command;
  }
  const CommandResult pfa = runMocap("pfa --help", dir);
  for (const char* option : {"--markers", "--exclude", "--threads", "--random", "--progress", "--curve"})
    EXPECT_NE(pfa.out.find(option), std::string::npos) << option;
  EXPECT_NE(runMocap("clean -h", dir).out.find("--spike-threshold"), std::string::npos);
  // Defaults and ranges come from the definitions.
  EXPECT_NE(runMocap("clean --help", dir).out.find("--order K=3"), std::string::npos);
  EXPECT_NE(runMocap("clean --help", dir).out.find("B-spline order (whole number in [2, 7])"), std::string::npos);
  const CommandResult bad = runMocap("info", dir);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_EQ(bad.err, "mocap info: FILE is required\nusage: mocap info FILE [OPTIONS] (mocap info --help for more)\n");
  EXPECT_EQ(bad.err.find("commands:"), std::string::npos) << bad.err;
  EXPECT_EQ(runMocap("help", dir).out, all.out);
}

// The README's command table is the output of `mocap --help`.
TEST(Cli, ReadmeListsTheCommandsAsMocapHelpDoes)
{
  test::TempDir dir;
  const std::string readme = readFileBytes(std::filesystem::path(checkout::sourceDir()) / "README.md");
  const std::size_t section = readme.find("## The `mocap` command line");
  ASSERT_NE(section, std::string::npos);
  const std::size_t open = readme.find("```\n", section);
  ASSERT_NE(open, std::string::npos);
  const std::size_t close = readme.find("\n```\n", open);
  ASSERT_NE(close, std::string::npos);
  const std::string block = readme.substr(open + 4, close + 1 - (open + 4));
  const CommandResult help = runMocap("--help", dir);
  ASSERT_EQ(help.exitCode, 0);
  EXPECT_EQ(block, help.out) << "README.md (-) and mocap --help (+) differ; paste mocap --help into the README:\n"
                             << lineDiff(block, help.out);
}

// Bad values are usage errors (exit 2) that name the option and what it allows; nothing runs.
TEST(Cli, OutOfRangeValuesInvalidChoicesAndUnknownOptionsGiveExitTwoNamingTheOption)
{
  test::TempDir dir;
  const std::string take = q(test::sampleTake());
  const std::string out = " -o " + q(dir.file("x.c3d"));
  const struct
  {
    std::string arguments;
    std::string message;
  } cases[] = {
      {"clean " + take + out + " --order 8", "mocap clean: --order: 8 not in [2, 7]"},
      {"clean " + take + out + " --order=1", "mocap clean: --order: 1 not in [2, 7]"},
      {"clean " + take + out + " --min-valid 2", "mocap clean: --min-valid: 2 not in [0, 1]"},
      {"clean " + take + out + " --order three", "mocap clean: --order: 'three' is not a whole number"},
      {"eval-smooth " + take + " --noise -1", "mocap eval-smooth: --noise: -1 not in [0, 10000]"},
      {"eval-spikes " + take + " --amplitude x", "mocap eval-spikes: --amplitude: 'x' is not a number"},
      {"clean " + take + out + " --smooth wavelet",
       "mocap clean: --smooth: 'wavelet' is not one of bspline, butterworth, gcvspl, savgol, off"},
      {"pfa " + take + " --method=best", "mocap pfa: --method: 'best' is not one of pfa, greedy"},
      {"deform --mesh m.obj --binding b.json --take " + take + " -o x.pc2 --kernel cubic",
       "mocap deform: --kernel: 'cubic' is not one of exp, gaussian, biharmonic, thin-plate"},
      {"convert " + take + " " + q(dir.file("x.c3d")) + " --units furlong",
       "mocap convert: --units: 'furlong' is not mm, cm or m"},
      {"info " + take + " --bogus", "mocap info: The following argument was not expected: --bogus"},
      {"clean " + take + out + " --max-gap 10 --max-gap-seconds 1", "mocap clean: --max-gap-seconds excludes --max-gap"},
      {"fix-swaps " + take, "mocap fix-swaps: --output is required"},
      {"frobnicate x", "mocap: unknown command 'frobnicate'"},
  };
  for (const auto& c : cases) {
    const CommandResult run = runMocap(c.arguments, dir);
    EXPECT_EQ(run.exitCode, 2) << c.arguments;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << c.arguments << "\n" << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 2) << run.err;
    EXPECT_NE(run.err.find("--help"), std::string::npos) << "a hint to the usage: " << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.c3d")));
}

// Both --opt VALUE and --opt=VALUE; a repeated option's last value wins; whole numbers are decimal
// ("010" is ten, not octal eight); negative numbers are values, not options.
TEST(Cli, OptionValuesReadAsBefore)
{
  test::TempDir dir;
  const std::string nose = q(test::dataFile("trc/NoseMoCap.trc"));
  const CommandResult spikes = runMocap("eval-spikes " + nose + " --count=7 --count 010 --seed 3 --json", dir);
  ASSERT_EQ(spikes.exitCode, 0) << spikes.err;
  EXPECT_NE(spikes.out.find("\"count\": 10,"), std::string::npos) << spikes.out.substr(0, 300);
  EXPECT_NE(spikes.out.find("\"seed\": 3,"), std::string::npos);
  const CommandResult bind = runMocap("bind --mesh m.obj --take " + nose + " -o x.json --neutral -5", dir);
  EXPECT_EQ(bind.err.find("--neutral"), std::string::npos) << "-5 is --neutral's value: " << bind.err;
}

TEST(Cli, ConvertWritesEveryFormatAndTrcReadsBack)
{
  test::TempDir dir;
  for (const char* name : {"take.trc", "take.csv", "take.bvh", "take.c3d", "take.fbx"}) {
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

TEST(Cli, ConvertWritesTheMarkersAsFbxWithTheAxesAndUnitsAsked)
{
  test::TempDir dir;
  const CommandResult run = runMocap(
      "convert " + q(test::sampleTake()) + " " + q(dir.file("take.fbx")) + " --up y --units cm", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::vector<test::FbxTestNode> top = test::readFbxForTest(readFileBytes(dir.file("take.fbx")));
  std::map<std::string, double> global;
  for (const test::FbxTestNode& p : test::fbxNode(top, "GlobalSettings").at("Properties70").children)
    global[p.properties.at(0).text] =
        p.properties.at(4).type == 'D' ? p.properties.at(4).number : static_cast<double>(p.properties.at(4).integer);
  EXPECT_EQ(global["UpAxis"], 1.0);
  EXPECT_EQ(global["UnitScaleFactor"], 1.0);
  EXPECT_EQ(global["CustomFrameRate"], 100.0);
  const Take take = readTake(test::sampleTake());
  std::size_t nulls = 0;
  for (const test::FbxTestNode& object : test::fbxNode(top, "Objects").children)
    nulls += object.name == "Model" && object.properties.at(2).text == "Null";
  EXPECT_EQ(nulls, markerPoints(take).size() + 1) << "a root and a null per marker";

  // --up is for FBX only; an unwritable output is a clear error.
  EXPECT_EQ(runMocap("convert " + q(test::sampleTake()) + " " + q(dir.file("x.trc")) + " --up y", dir).exitCode, 2);
  EXPECT_EQ(runMocap("convert " + q(test::sampleTake()) + " " + q(dir.file("x.fbx")) + " --up x", dir).exitCode, 2);
  const CommandResult unwritable =
      runMocap("convert " + q(test::sampleTake()) + " " + q(dir.file("take.fbx") / "x.fbx"), dir);
  EXPECT_EQ(unwritable.exitCode, 1);
  EXPECT_NE(unwritable.err.find("x.fbx"), std::string::npos) << unwritable.err;

  // --reduce MM keys each curve within the tolerance, in mm whatever the take's units, and says so.
  std::size_t everyFrame = 0;
  for (const test::FbxTestNode& object : test::fbxNode(top, "Objects").children)
    if (object.name == "AnimationCurve")
      everyFrame += object.at("KeyTime").properties.at(0).integers.size();
  const CommandResult reduced = runMocap(
      "convert " + q(test::sampleTake()) + " " + q(dir.file("reduced.fbx")) + " --units cm --reduce 0.1", dir);
  ASSERT_EQ(reduced.exitCode, 0) << reduced.err;
  std::size_t kept = 0;
  const std::vector<test::FbxTestNode> reducedTop = test::readFbxForTest(readFileBytes(dir.file("reduced.fbx")));
  for (const test::FbxTestNode& object : test::fbxNode(reducedTop, "Objects").children)
    if (object.name == "AnimationCurve")
      kept += object.at("KeyTime").properties.at(0).integers.size();
  EXPECT_LT(kept, everyFrame);
  EXPECT_NE(reduced.out.find("tolerance 0.1 mm"), std::string::npos) << reduced.out;
  std::cout << "[ keys ] the sample's markers at 0.1 mm: " << kept << " of " << everyFrame << " keys (with Visibility)\n";
  EXPECT_EQ(runMocap("convert " + q(test::sampleTake()) + " " + q(dir.file("x.trc")) + " --reduce 1", dir).exitCode, 2);
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

TEST(Cli, EvaluationCommandsPrintJson)
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
  EXPECT_EQ(runMocap("eval-spikes " + nose + " --amplitude -5", dir).exitCode, 2);
  EXPECT_EQ(runMocap("eval-smooth " + q(dir.file("missing.trc")), dir).exitCode, 1);
}

// Apart from the evaluation commands: each is tens of seconds under the sanitizers, and two tests
// run side by side where one would hold a slot alone at the end of the pass.
TEST(Cli, PlanningCommandPrintsJsonAndTheCurve)
{
  test::TempDir dir;
  const std::string nose = q(test::dataFile("trc/NoseMoCap.trc"));
  const CommandResult pfa =
      runMocap("pfa " + nose + " --restarts 20 --k 5:7 --json --curve " + q(dir.file("curve.csv")), dir);
  ASSERT_EQ(pfa.exitCode, 0) << pfa.err;
  EXPECT_NE(pfa.out.find("\"recommended\""), std::string::npos);
  EXPECT_GT(std::filesystem::file_size(dir.file("curve.csv")), 50u);
  const CommandResult two = runMocap("pfa " + nose + " --restarts 5 --k=5 " + nose + " --json", dir);
  ASSERT_EQ(two.exitCode, 0) << two.err;
  const std::size_t inputs = two.out.find("\"inputs\": [");
  ASSERT_NE(inputs, std::string::npos);
  const std::string listed = two.out.substr(inputs, two.out.find(']', inputs) - inputs);
  std::size_t takes = 0;
  for (std::size_t at = listed.find("NoseMoCap.trc"); at != std::string::npos; at = listed.find("NoseMoCap.trc", at + 1))
    ++takes;
  EXPECT_EQ(takes, 2u) << "both TAKEs, with options between them: " << listed;
  EXPECT_EQ(runMocap("pfa " + nose + " --k 9:3", dir).exitCode, 2);
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

TEST(Cli, CleanStabilizesWithSavedHeadMarkersAndGuessesNone)
{
  test::TempDir dir;
  const std::string roots = "root-1,root-2,root-3,root-4,root-5,root-6";
  // The sample names no saved head markers: a bare --stabilize is refused, naming the flag.
  const CommandResult bare =
      runMocap("clean " + q(test::sampleTake()) + " -o " + q(dir.file("x.c3d")) + " --stabilize", dir);
  EXPECT_EQ(bare.exitCode, 2);
  EXPECT_NE(bare.err.find("has no head markers saved with it; name them: --stabilize LABEL"), std::string::npos)
      << bare.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.c3d")));
  // A take the studio saved with its head markers: a bare --stabilize uses them.
  Take saved = readTake(test::sampleTake());
  setHeadMarkers(saved, {"root-1", "root-2", "root-3", "root-4", "root-5", "root-6"});
  writeTake(saved, dir.file("saved.c3d"));
  // Both runs stamp their history with one time, so the two files can be compared byte for byte.
  ::setenv("SOURCE_DATE_EPOCH", "1780000000", 1);
  const CommandResult run = runMocap("clean " + q(dir.file("saved.c3d")) + " -o " + q(dir.file("a.c3d")) +
                                         " --report " + q(dir.file("a.json")) + " --stabilize",
                                     dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(readFileBytes(dir.file("a.json")).find("\"root-6\""), std::string::npos);
  ASSERT_EQ(runMocap("clean " + q(dir.file("saved.c3d")) + " -o " + q(dir.file("b.c3d")) + " --stabilize " + roots, dir)
                .exitCode,
            0);
  ::unsetenv("SOURCE_DATE_EPOCH");
  EXPECT_TRUE(readFileBytes(dir.file("a.c3d")) == readFileBytes(dir.file("b.c3d"))) << "the same markers, named";
  EXPECT_EQ(headMarkers(readTake(dir.file("a.c3d"))), headMarkers(saved)) << "the cleaned take keeps them";
}

TEST(Cli, CleanByDefaultLeavesLongGapsOpenAndSaysWhy)
{
  test::TempDir dir;
  const CommandResult run = runMocap("clean " + q(test::sampleTake()) + " -o " + q(dir.file("clean.c3d")) +
                                         " --report " + q(dir.file("report.json")),
                                     dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string report = readFileBytes(dir.file("report.json"));
  // The defaults are printed with the fill.
  for (const char* option : {"\"max_gap_frames\": 50,", "\"max_gap_seconds\": 0.5,", "\"extrapolate\": false,",
                             "\"min_valid_fraction\": 0.2,", "\"unlimited\": false,"})
    EXPECT_NE(report.find(option), std::string::npos) << option;
  // Unlabeled1 (35 valid frames) keeps its 703- and 865-frame gaps, listed with the reason.
  const std::size_t open = report.find("\"unfilled\": [");
  ASSERT_NE(open, std::string::npos);
  const std::string unfilled = report.substr(open);
  for (const char* length : {"703", "865"})
    EXPECT_NE(unfilled.find(std::string("\"marker\": \"Unlabeled1\",\n        \"first_frame\": ") +
                            (length[0] == '7' ? "864" : "2136") + ",\n        \"length\": " + length +
                            ",\n        \"cause\": \"rarely_valid\",\n        \"reason\": \"marker valid in only 1.2 %"),
              std::string::npos)
        << length << "\n" << unfilled.substr(0, 2000);
  EXPECT_NE(unfilled.find("\"cause\": \"too_long\",\n        \"reason\": \"longer than the longest gap to fill (50 frames, "
                          "0.5 s)\""),
            std::string::npos);
  EXPECT_EQ(report.find("\"unfilled_gaps\": 0,"), std::string::npos) << "some gaps are left open";
  const CommandResult info = runMocap("info " + q(dir.file("clean.c3d")) + " --json", dir);
  ASSERT_EQ(info.exitCode, 0);
  EXPECT_NE(info.out.find("\"marker\": \"Unlabeled1\""), std::string::npos) << "nothing invented for Unlabeled1";

  // Asked for, everything is filled as before: --max-gap 0 is unlimited.
  const CommandResult all = runMocap("clean " + q(test::sampleTake()) + " -o " + q(dir.file("all.c3d")) +
                                         " --max-gap 0 --extrapolate --min-valid 0 --report " + q(dir.file("all.json")),
                                     dir);
  ASSERT_EQ(all.exitCode, 0) << all.err;
  const std::string everything = readFileBytes(dir.file("all.json"));
  EXPECT_NE(everything.find("\"unfilled_gaps\": 0,"), std::string::npos);
  EXPECT_NE(everything.find("\"unlimited\": true,"), std::string::npos);
  const CommandResult seconds = runMocap("clean " + q(test::sampleTake()) + " -o " + q(dir.file("s.c3d")) +
                                             " --max-gap-seconds 2 --report " + q(dir.file("s.json")),
                                         dir);
  ASSERT_EQ(seconds.exitCode, 0) << seconds.err;
  EXPECT_NE(readFileBytes(dir.file("s.json")).find("\"max_gap_frames\": 200,"), std::string::npos);
  EXPECT_EQ(runMocap("clean " + q(test::sampleTake()) + " -o " + q(dir.file("x.c3d")) + " --max-gap 10 --max-gap-seconds 1",
                     dir)
                .exitCode,
            2);
  EXPECT_EQ(runMocap("clean " + q(test::sampleTake()) + " -o " + q(dir.file("x.c3d")) + " --min-valid 2", dir).exitCode, 2);
}

// A file in metres without POINT:UNITS (a real SIMI export, every point invalid): info says both,
// and convert --input-units names the unit without rescaling a number.
TEST(Cli, InputUnitsNamesTheUnitAFileGotWrongWithoutRescaling)
{
  test::TempDir dir;
  const std::string simi = q(test::dataFile("c3d/sample16/basketball.c3d"));
  const CommandResult info = runMocap("info " + simi, dir);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_NE(info.err.find("every sample is marked invalid"), std::string::npos) << info.err;
  EXPECT_NE(info.err.find("--input-units m"), std::string::npos) << info.err;
  const CommandResult named = runMocap("convert " + simi + " " + q(dir.file("m.trc")) + " --input-units m", dir);
  ASSERT_EQ(named.exitCode, 0) << named.err;
  std::vector<std::string> warnings;
  const Take before = readTake(test::dataFile("c3d/sample16/basketball.c3d"));
  const Take after = readTake(dir.file("m.trc"), &warnings);
  EXPECT_EQ(after.units(), LengthUnit::Metre);
  for (const std::string& warning : warnings)
    EXPECT_EQ(warning.find("span"), std::string::npos) << warning;
  const CommandResult scaled = runMocap("convert " + simi + " " + q(dir.file("mm.c3d")) + " --input-units m --units mm", dir);
  ASSERT_EQ(scaled.exitCode, 0) << scaled.err;
  EXPECT_EQ(readTake(dir.file("mm.c3d")).units(), LengthUnit::Millimetre);
  const CommandResult bad = runMocap("convert " + simi + " " + q(dir.file("x.trc")) + " --input-units furlong", dir);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("'furlong' is not mm, cm or m"), std::string::npos) << bad.err;
  EXPECT_EQ(before.frameCount(), after.frameCount());
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

TEST(Cli, TrackLabelsAnUnlabelledC3dWithATemplateAndFixSwapsRepairs)
{
  test::TempDir dir;
  const Take truth = readTake(test::dataFile("trc/NoseMoCap.trc"));
  const UnlabelledCopy copy = makeUnlabelledCopy(truth);
  writeTake(copy.take, dir.file("unlabelled.c3d"));
  writeMarkerSet(markerSetFromTake(truth), dir.file("set.json"));
  for (const std::string& templ : {q(test::dataFile("trc/NoseMoCap.trc")), q(dir.file("set.json"))}) {
    const CommandResult run = runMocap("track " + q(dir.file("unlabelled.c3d")) + " -o " + q(dir.file("out.c3d")) +
                                           " --template " + templ + " --max-speed 8 --json",
                                       dir);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (const char* key : {"\"fragments\"", "\"labelled_fragments\"", "\"unlabelled_samples\"", "\"gate\": 8"})
      EXPECT_NE(run.out.find(key), std::string::npos) << key << "\n" << run.out;
    // C3D stores floats: compare against the truth as written and read back.
    writeTake(truth, dir.file("truth.c3d"));
    const Take truthAsC3d = readTake(dir.file("truth.c3d"));
    EXPECT_GE(labelAgreement(truthAsC3d, readTake(dir.file("out.c3d")), copy.kept), 0.995);
  }

  std::vector<InjectedSwap> injected;
  writeTake(makeSwappedCopy(truth, {}, injected), dir.file("swapped.trc"));
  const CommandResult fix = runMocap("fix-swaps " + q(dir.file("swapped.trc")) + " -o " + q(dir.file("fixed.trc")) +
                                         " --report " + q(dir.file("swaps.json")),
                                     dir);
  ASSERT_EQ(fix.exitCode, 0) << fix.err;
  const std::string report = readFileBytes(dir.file("swaps.json"));
  EXPECT_NE(report.find("\"count\": " + std::to_string(2 * injected.size())), std::string::npos) << report;
  EXPECT_NE(report.find("\"first\": \""), std::string::npos);
  writeTake(truth, dir.file("truth.trc"));
  EXPECT_EQ(labelAgreement(readTake(dir.file("truth.trc")), readTake(dir.file("fixed.trc")), {}), 1.0);

  const CommandResult eval = runMocap("eval-track " + q(test::dataFile("trc/NoseMoCap.trc")) + " --seed 3 --json", dir);
  ASSERT_EQ(eval.exitCode, 0) << eval.err;
  for (const char* key : {"\"label_recovery\"", "\"swaps_found\"", "\"false_alarms\""})
    EXPECT_NE(eval.out.find(key), std::string::npos) << key;

  EXPECT_EQ(runMocap("track " + q(dir.file("unlabelled.c3d")), dir).exitCode, 2) << "-o is required";
  EXPECT_EQ(runMocap("track " + q(dir.file("unlabelled.c3d")) + " -o " + q(dir.file("x.c3d")) + " --max-speed -3", dir)
                .exitCode,
            2);
  writeFileAtomically(dir.file("bad.json"), "{\"format\": \"mocap-marker-set\", \"version\": 1, \"markers\": [");
  const CommandResult bad = runMocap("track " + q(dir.file("unlabelled.c3d")) + " -o " + q(dir.file("x.c3d")) +
                                         " --template " + q(dir.file("bad.json")),
                                     dir);
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find("bad.json"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.c3d")));
}

TEST(Cli, TrackReadsACsvOfRawPoints)
{
  test::TempDir dir;
  std::string csv = "frame,x,y,z\n";
  for (int f = 0; f < 50; ++f)  // three points 40 mm apart drifting 1 mm per frame
    for (int p = 0; p < 3; ++p)
      csv += std::to_string(f) + "," + std::to_string(40 * p + f) + ",0,0\n";
  writeFileAtomically(dir.file("points.csv"), csv);
  const CommandResult run = runMocap("track " + q(dir.file("points.csv")) + " -o " + q(dir.file("out.trc")) + " --json", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("\"fragments\": 3"), std::string::npos) << run.out;
  const Take out = readTake(dir.file("out.trc"));
  EXPECT_EQ(out.markerCount(), 3);
  EXPECT_EQ(out.frameCount(), 50);
  EXPECT_EQ(out.validFraction(), 1.0);
  writeFileAtomically(dir.file("broken.csv"), "0,1,2,3\n1,2,oops,4\n");
  const CommandResult broken = runMocap("track " + q(dir.file("broken.csv")) + " -o " + q(dir.file("y.trc")), dir);
  EXPECT_EQ(broken.exitCode, 1);
  EXPECT_NE(broken.err.find("line 2"), std::string::npos) << broken.err;
}

} // namespace
} // namespace mocap
