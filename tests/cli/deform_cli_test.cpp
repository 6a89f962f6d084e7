// `mocap bind`, `mocap deform`, `mocap rig` and `mocap solve` end to end on the bundled take, the
// MediaPipe face and the bundled ICT FaceKit rig.
#include "../core/fbx_test_reader.h"
#include "../core/test_support.h"

#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/io/gltf_rig_reader.h"
#include "mocap/io/pc2_io.h"
#include "mocap/io/obj_io.h"
#include "mocap/io/ply_io.h"
#include "checkout_paths.h"

#include <gtest/gtest.h>

#include <iostream>

#include <algorithm>
#include <map>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <sys/wait.h>

namespace mocap {
namespace {

struct Outcome
{
  int exitCode = -1;
  std::string out;
  std::string err;
};

// Runs `mocap ARGUMENTS` through the shell with stdout and stderr captured in files of `dir`.
Outcome mocap(const std::string& arguments, const test::TempDir& dir)
{
  const std::string command = std::string("'") + checkout::cliProgram() + "' " + arguments + " >'" +
                              dir.file("out.txt").string() + "' 2>'" + dir.file("err.txt").string() + "'";
  const int status = std::system(command.c_str());
  Outcome run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = readFileBytes(dir.file("out.txt"));
  run.err = readFileBytes(dir.file("err.txt"));
  return run;
}

std::string faceMesh()
{
  return "'" + test::dataFile("face_mesh/canonical_face_model.obj").string() + "'";
}

std::string sample()
{
  return "'" + test::sampleTake().string() + "'";
}

const char* kStabilize = "--stabilize root-1,root-2,root-3,root-4,root-5,root-6";

std::string faceMarkers()
{
  std::string list;
  for (int section = 1; section <= 14; ++section)
    for (int k = 1; k <= (section == 10 || section >= 13 ? 3 : 2); ++k)
      list += (list.empty() ? "" : ",") + ("section" + std::to_string(section) + "-" + std::to_string(k));
  return list;
}

TEST(DeformCli, BindThenDeformWritesAPointCacheAndTheIssueJsonKeys)
{
  test::TempDir dir;
  const std::string binding = dir.file("bind.json").string();
  const Outcome bound0 = mocap("bind --mesh " + faceMesh() + " --take " + sample() + " " + kStabilize + " --markers " +
                             faceMarkers() + " -o '" + binding + "'",
                         dir);
  ASSERT_EQ(bound0.exitCode, 0) << bound0.err;
  EXPECT_NE(bound0.out.find("bound 31 markers"), std::string::npos) << bound0.out;
  const JsonValue bound = parseJson(readFileBytes(binding), binding);
  ASSERT_NE(bound.find("markers", "binding"), nullptr);
  EXPECT_EQ(bound.find("markers", "binding")->object("markers").size(), 31u);
  // The take is in mm and the mesh in cm: the similarity scale is about 0.1.
  const double scale = bound.find("alignment", "binding")->find("scale", "alignment")->number("scale");
  EXPECT_GT(scale, 0.07);
  EXPECT_LT(scale, 0.13);

  for (const std::string method : {"rbf", "laplacian"}) {
    const std::string cache = dir.file(method + ".pc2").string();
    const Outcome run = mocap("deform --mesh " + faceMesh() + " --binding '" + binding + "' --take " + sample() + " " +
                              kStabilize + " --method " + method + " --frames 1:200 -o '" + cache + "' --json",
                          dir);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const JsonValue report = parseJson(run.out, "stdout");
    for (const char* key : {"vertices", "frames", "setup_seconds", "frame_seconds_mean", "frame_seconds_p95",
                            "leave_out_error_mm"})
      ASSERT_NE(report.find(key, "report"), nullptr) << key << " missing in " << run.out;
    EXPECT_EQ(report.find("vertices", "report")->number("vertices"), 468);
    EXPECT_EQ(report.find("frames", "report")->number("frames"), 200);
    const double error = report.find("leave_out_error_mm", "report")->number("leave_out_error_mm");
    const double rest = report.find("leave_out", "report")->find("rest_error_mm", "leave_out")->number("rest_error_mm");
    EXPECT_GT(error, 0.0);
    EXPECT_LT(error, rest) << method << ": deforming must beat leaving the mesh at rest";
    const PointCache points = readPc2(cache);
    ASSERT_EQ(points.samples.size(), 200u);
    EXPECT_EQ(points.samples[0].rows(), 468);
    EXPECT_EQ(points.startFrame, 1.0f);
    EXPECT_TRUE(std::filesystem::exists(dir.file(method + ".obj")));
  }

  const Outcome perFrame = mocap("deform --mesh " + faceMesh() + " --binding '" + binding + "' --take " + sample() +
                                 " --frames 10:12 --ply --kernel thin-plate --regions --scale per-axis --leave-out 0 -o '" +
                                 dir.file("frames").string() + "'",
                             dir);
  ASSERT_EQ(perFrame.exitCode, 0) << perFrame.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("frames") / "canonical_face_model_neutral.obj"));
  EXPECT_EQ(readPly(dir.file("frames") / "canonical_face_model_0003.ply").vertexCount(), 468);
  EXPECT_FALSE(std::filesystem::exists(dir.file("frames") / "canonical_face_model_0004.ply"));
}

TEST(DeformCli, BadUsageAndBadInputGiveClearErrors)
{
  test::TempDir dir;
  Outcome run = mocap("deform --binding b.json --take " + sample() + " -o x.pc2", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("--mesh is required"), std::string::npos) << run.err;

  writeFileAtomically(dir.file("off.json"), R"({"markers": {"section1-1": 5000, "section1-2": 2, "section2-1": 3}})");
  run = mocap("deform --mesh " + faceMesh() + " --binding '" + dir.file("off.json").string() + "' --take " + sample() +
                  " -o '" + dir.file("x.pc2").string() + "'",
              dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("section1-1 is bound off the mesh"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.pc2")));

  writeFileAtomically(dir.file("dup.json"),
                      R"({"markers": {"section1-1": 5, "section1-2": 5, "section2-1": 3, "section2-2": 9}})");
  run = mocap("deform --mesh " + faceMesh() + " --binding '" + dir.file("dup.json").string() + "' --take " +
                  sample() + " -o '" + dir.file("x.pc2").string() + "'",
              dir);
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.err.find("section1-1 and section1-2 are at the same mesh point"), std::string::npos) << run.err;

  run = mocap("deform --mesh " + faceMesh() + " --binding '" + dir.file("dup.json").string() + "' --take " +
                  sample() + " --kernel cubic -o x.pc2",
              dir);
  EXPECT_EQ(run.exitCode, 2);
  run = mocap("bind --mesh " + faceMesh() + " --take " + sample() + " --markers section1-1,section1-2,section2-1 " +
                  "--pairs section1-1=1,section1-2=2 -o '" + dir.file("b.json").string() + "'",
              dir);
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.err.find("at least 3 correspondences"), std::string::npos) << run.err;
}

TEST(DeformCli, FrameRangesAreReadWholeAndMustLieInTheTake)
{
  test::TempDir dir;
  const std::string deform = "deform --mesh " + faceMesh() + " --binding '" +
                             test::dataFile("../../resources/sample/Facial-Sing.binding.json").string() + "' --take " +
                             sample() + " --leave-out 0 -o '" + dir.file("x.pc2").string() + "' --frames";
  const auto expectError = [&](const std::string& frames, const std::string& fragment) {
    const Outcome run = mocap(deform + frames, dir);
    EXPECT_EQ(run.exitCode, 2) << frames;
    EXPECT_NE(run.err.find(fragment), std::string::npos) << run.err;
  };
  expectError(" 10:20x",
              "--frames needs FIRST:LAST frame numbers of the take (1…3000), not '10:20x': LAST '20x' is not a whole number");
  expectError(" 10x:20", "not '10x:20': FIRST '10x' is not a whole number");
  expectError(" 10:20:30", "LAST '20:30' is not a whole number");
  expectError(" 20:10", "LAST 10 is before FIRST 20");
  expectError("=-5:10", "FIRST -5 is less than 1");
  expectError(" 2990:3001", "LAST 3001 is more than 3000");
  expectError(" 1:99999999999999999999", "LAST '99999999999999999999' does not fit a 64-bit whole number");
  expectError(" :20", "FIRST is empty");
  expectError(" 10-20", "no ':' between FIRST and LAST");
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.pc2")));
}

std::vector<std::string> csvLines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::string solveArguments(const test::TempDir& dir)
{
  return "solve --mesh '" + dir.file("neutral.obj").string() + "' --shapes '" + dir.file("shapes").string() +
         "' --binding '" + test::dataFile("../../resources/sample/Facial-Sing.binding.json").string() + "' --take " +
         sample() + " " + kStabilize;
}

TEST(SolveCli, WritesWeightCurvesInBothLayoutsAndTheIssueJsonKeys)
{
  test::TempDir dir;
  writeSmallRig(dir);
  const std::string curves = dir.file("weights.csv").string();
  const Outcome run = mocap(solveArguments(dir) + " -o '" + curves + "' --json", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const JsonValue json = parseJson(run.out, "solve --json");
  EXPECT_EQ(json.find("method", "solve")->string("method"), "temporal");
  for (const char* key : {"lambda", "setup_seconds", "frames_per_second", "leave_out_error_mm"})
    EXPECT_TRUE(json.find(key, "solve")->isNumber()) << key;
  const JsonValue& residual = *json.find("residual_mm", "solve");
  for (const char* key : {"mean", "p95", "max"})
    EXPECT_GE(residual.find(key, "residual")->number(key), 0.0) << key;
  EXPECT_TRUE(json.find("active_shapes", "solve")->isArray());
  EXPECT_EQ(json.find("markers", "solve")->number("markers"), 31.0);
  EXPECT_TRUE(json.find("notes", "solve")->array("notes").empty()) << "stabilized: nothing to note";

  const std::vector<std::string> plain = csvLines(readFileBytes(curves));
  ASSERT_EQ(plain.size(), 3001u);  // header + the take's 3000 frames
  EXPECT_EQ(plain[0], "Frame,Time,browInnerUp,jawOpen,mouthSmile_L");
  EXPECT_EQ(plain[1].substr(0, 4), "1,0,");
  for (std::size_t i = 1; i < plain.size(); i += 97) {
    std::istringstream row(plain[i]);
    std::string cell;
    for (int c = 0; std::getline(row, cell, ','); ++c)
      if (c >= 2) {
        EXPECT_GE(std::stod(cell), 0.0);
        EXPECT_LE(std::stod(cell), 1.0);
      }
  }

  // Live Link Face's own layout: the header of a real recording (52 ARKit curves in the app's
  // order, then head and eyes), 61 values a row, timecodes at the app's 60 frames a second.
  const std::string live = dir.file("live.csv").string();
  const Outcome liveRun = mocap(solveArguments(dir) + " --format livelink --leave-out 0 -o '" + live + "'", dir);
  ASSERT_EQ(liveRun.exitCode, 0) << liveRun.err;
  const std::vector<std::string> liveLines = csvLines(readFileBytes(live));
  ASSERT_EQ(liveLines.size(), 3001u);
  const std::string recording = readFileBytes(test::dataFile("livelink_face/alex_rom_4_first200.csv"));
  EXPECT_EQ(liveLines[0], recording.substr(0, recording.find('\n')));
  EXPECT_EQ(liveLines[1].substr(0, 19), "00:00:00:00.000,61,");
  EXPECT_EQ(liveLines[2].substr(0, 19), "00:00:00:00.600,61,") << "the take's 100 Hz in the app's 60";
  EXPECT_EQ(liveLines[101].substr(0, 19), "00:00:01:00.000,61,");
  // Each of the rig's shapes in its curve (Apple's names: browInnerUp is BrowInnerUp), the head's
  // turn from the stabilization's markers, the eyes at rest.
  const auto cells = [](const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');)
      fields.push_back(cell);
    return fields;
  };
  const std::vector<std::string> header = cells(liveLines[0]);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  double largestDifference = 0.0, largestHeadTurn = 0.0;
  for (std::size_t i = 1; i < liveLines.size(); ++i) {
    const std::vector<std::string> row = cells(liveLines[i]), plainRow = cells(plain[i]);
    ASSERT_EQ(row.size(), 63u) << i;
    const std::pair<const char*, std::size_t> pairs[] = {{"BrowInnerUp", 2}, {"JawOpen", 3}, {"MouthSmileLeft", 4}};
    for (const auto& [name, plainColumn] : pairs)
      largestDifference = std::max(largestDifference, std::abs(std::stod(row[column(name)]) - std::stod(plainRow[plainColumn])));
    EXPECT_EQ(std::stod(row[column("MouthSmileRight")]), 0.0);
    for (const char* eye : {"LeftEyeYaw", "RightEyePitch", "RightEyeRoll"})
      EXPECT_EQ(std::stod(row[column(eye)]), 0.0);
    for (const char* head : {"HeadYaw", "HeadPitch", "HeadRoll"})
      largestHeadTurn = std::max(largestHeadTurn, std::abs(std::stod(row[column(head)])));
  }
  EXPECT_LT(largestDifference, 1e-9) << "the values printed with 10 decimals";
  EXPECT_GT(largestHeadTurn, 0.01) << "the singer's head turns by more than half a degree";
  EXPECT_LT(largestHeadTurn, 1.0) << "and by less than a radian";
  std::cout << "[ head ] largest head angle in the sample: " << largestHeadTurn << " rad\n";
}

TEST(SolveCli, WritesTheSolvedMeshAsAPointCache)
{
  test::TempDir dir;
  writeSmallRig(dir);
  const std::string cache = dir.file("solved.pc2").string();
  const Outcome run = mocap(solveArguments(dir) + " --method ridge --leave-out 0 -o '" + cache + "'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("solved 3000 frames to 3 shapes from 31 markers"), std::string::npos) << run.out;
  const PointCache pc2 = readPc2(cache);
  EXPECT_EQ(pc2.samples.size(), 3000u);
  EXPECT_EQ(pc2.samples.front().rows(), 468);
}

TEST(SolveCli, WritesTheRigWithItsAnimatedWeightsAsGlb)
{
  test::TempDir dir;
  writeSmallRig(dir);
  const std::string glb = dir.file("solved.glb").string(), csv = dir.file("solved.csv").string();
  ASSERT_EQ(mocap(solveArguments(dir) + " --leave-out 0 -o '" + glb + "'", dir).exitCode, 0);
  ASSERT_EQ(mocap(solveArguments(dir) + " --leave-out 0 -o '" + csv + "'", dir).exitCode, 0);
  const std::string bytes = readFileBytes(glb);
  ASSERT_GT(bytes.size(), 12u);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  // The GLB holds the same 3000 × 3 weights the CSV does (as float32): 36 000 bytes of animation
  // output plus the 3000 key times, beside the mesh.
  EXPECT_GT(bytes.size(), 3000u * 4u * 4u);
}

TEST(SolveCli, ReduceKeepsFewerKeyFramesWithinTheTolerance)
{
  test::TempDir dir;
  writeSmallRig(dir);
  const std::string glb = dir.file("reduced.glb").string();
  const Outcome run = mocap(solveArguments(dir) + " --leave-out 0 --reduce 0.01 --json -o '" + glb + "'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const JsonValue json = parseJson(run.out, "solve --json");
  ASSERT_NE(json.find("key_reduction", "solve"), nullptr) << run.out;
  const JsonValue& reduction = *json.find("key_reduction", "solve");
  const double before = reduction.find("keys_before", "k")->number("keys_before");
  const double after = reduction.find("keys_after", "k")->number("keys_after");
  EXPECT_EQ(before, 3000.0);
  EXPECT_LT(after, before);
  EXPECT_GE(after, 2.0);
  EXPECT_LE(reduction.find("max_error", "k")->number("max_error"), 0.01);
  std::cout << "[ keys ] the sample solved to the small rig, tolerance 0.01: " << after << " of " << before
            << " key frames\n";

  // FBX keys each shape's curve on its own: never more keys than the shared key frames give it.
  const std::string fbx = dir.file("r.fbx").string();
  const Outcome perCurve = mocap(solveArguments(dir) + " --leave-out 0 --reduce 0.01 --json -o '" + fbx + "'", dir);
  ASSERT_EQ(perCurve.exitCode, 0) << perCurve.err;
  const JsonValue fbxJson = parseJson(perCurve.out, "solve --json");
  const JsonValue& curves = *fbxJson.find("key_reduction", "solve");
  const double shapes = 3.0;
  EXPECT_EQ(curves.find("keys_before", "k")->number("keys_before"), 3000.0 * shapes);
  const double fbxAfter = curves.find("keys_after", "k")->number("keys_after");
  EXPECT_LE(fbxAfter, after * shapes);
  EXPECT_LE(curves.find("max_error", "k")->number("max_error"), 0.01);
  double written = 0.0;
  const std::vector<test::FbxTestNode> fbxTop = test::readFbxForTest(readFileBytes(fbx));
  for (const test::FbxTestNode& object : test::fbxNode(fbxTop, "Objects").children)
    if (object.name == "AnimationCurve")
      written += static_cast<double>(object.at("KeyTime").properties.at(0).integers.size());
  EXPECT_EQ(written, fbxAfter) << "the file holds the keys the report counts";
  std::cout << "[ keys ] per curve in FBX: " << fbxAfter << " of " << 3000.0 * shapes << " keys\n";

  const Outcome csv = mocap(solveArguments(dir) + " --reduce 0.01 -o '" + dir.file("w.csv").string() + "'", dir);
  EXPECT_EQ(csv.exitCode, 2) << "weight CSV has no keys to reduce";
  EXPECT_NE(csv.err.find("--reduce applies to .glb and .fbx"), std::string::npos) << csv.err;
  EXPECT_EQ(mocap(solveArguments(dir) + " --reduce -1 -o '" + glb + "'", dir).exitCode, 2);
}

TEST(SolveCli, BadRigsAndOutputsGiveClearErrors)
{
  test::TempDir dir;
  writeSmallRig(dir);
  Outcome run = mocap(solveArguments(dir) + " -o '" + dir.file("w.txt").string() + "'", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find(".csv"), std::string::npos) << run.err;
  run = mocap("solve --mesh '" + dir.file("neutral.obj").string() + "' --binding b.json --take " + sample() + " -o w.csv", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("--shapes"), std::string::npos) << run.err;
  std::filesystem::create_directory(dir.file("empty"));
  run = mocap("solve --mesh '" + dir.file("neutral.obj").string() + "' --shapes '" + dir.file("empty").string() +
                  "' --binding b.json --take " + sample() + " -o '" + dir.file("w.csv").string() + "'",
              dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("has no .obj shapes"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("w.csv")));
}

std::string pfaRigArguments(const test::TempDir& dir, const std::string& binding)
{
  return "pfa " + sample() + " " + kStabilize + " --markers 'section*' --restarts 20 --random 2 --rig '" +
         dir.file("neutral.obj").string() + "' --rig-shapes '" + dir.file("shapes").string() + "' --binding '" +
         binding + "' --rig-frames 300";
}

TEST(PfaRigCli, JudgesEverySizeOnTheRigBesideTheKeyPoseMeasures)
{
  test::TempDir dir;
  writeSmallRig(dir);
  const std::string binding = test::dataFile("../../resources/sample/Facial-Sing.binding.json").string();
  const Outcome run = mocap(pfaRigArguments(dir, binding) + " --json", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const JsonValue json = parseJson(run.out, "pfa --json");
  const JsonValue& rig = *json.find("rig", "pfa");
  EXPECT_EQ(rig.find("bound_markers", "rig")->number("bound_markers"), 31.0);
  EXPECT_EQ(rig.find("planned_bound_markers", "rig")->number("planned"), 31.0);
  EXPECT_LE(rig.find("frames", "rig")->number("frames"), 300.0);
  EXPECT_LT(rig.find("planned_rig_weight_mse", "rig")->number("planned"), 1e-12);  // the full set against itself
  const auto& sizes = json.find("sizes", "pfa")->array("sizes");
  ASSERT_GE(sizes.size(), 20U);
  double smallest = -1.0, largest = -1.0;
  for (const JsonValue& size : sizes) {
    const double markers = size.find("markers", "size")->number("markers");
    for (const char* method : {"pfa", "greedy"}) {
      const JsonValue& layout = *size.find(method, "size");
      if (layout.isNull())
        continue;
      ASSERT_NE(layout.find("blendshape_mse", method), nullptr);  // the existing keys stay
      const JsonValue& mse = *layout.find("rig_weight_mse", method);
      EXPECT_EQ(mse.isNull(), markers < 3) << method << " at " << markers;  // too few bound markers
      if (mse.isNumber() && std::string(method) == "greedy")
        (markers == 3 ? smallest : largest) = mse.number("mse");
    }
    EXPECT_NE(size.find("random", "size")->find("rig_weight_mse", "random"), nullptr);
  }
  EXPECT_GT(smallest, largest) << "three markers judge worse than thirty";
  EXPECT_GE(largest, 0.0);

  const Outcome text = mocap(pfaRigArguments(dir, binding) + " --curve '" + dir.file("curve.csv").string() + "'", dir);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("rig-MSE"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("on the rig: weights off by"), std::string::npos) << text.out;
  EXPECT_NE(readFileBytes(dir.file("curve.csv")).find(",pfa_rig_weight_mse,greedy_rig_weight_mse,random_rig_weight_mse\n"),
            std::string::npos);
}

TEST(PfaRigCli, BadRigInputGivesClearErrorsBeforeAnyPlanning)
{
  test::TempDir dir;
  writeSmallRig(dir);
  Outcome run = mocap(pfaRigArguments(dir, dir.file("missing.bind.json").string()), dir);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("missing.bind.json"), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
  run = mocap("pfa " + sample() + " --rig '" + dir.file("neutral.obj").string() + "'", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("--rig needs --binding"), std::string::npos) << run.err;
  run = mocap("pfa " + sample() + " --rig-method ridge", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("--rig-method needs --rig"), std::string::npos) << run.err;
  run = mocap("pfa " + sample() + " --rig '" + dir.file("neutral.obj").string() + "' --binding b.json", dir);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("needs the folder with its shapes"), std::string::npos) << run.err;
}

// Every weight of a weights CSV: the rows after the header, the columns after Frame and Time.
std::vector<double> csvWeights(const std::string& text)
{
  std::vector<double> weights;
  const std::vector<std::string> lines = csvLines(text);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::istringstream row(lines[i]);
    std::string cell;
    for (int c = 0; std::getline(row, cell, ','); ++c)
      if (c >= 2)
        weights.push_back(std::stod(cell));
  }
  return weights;
}

std::string rigArguments(const test::TempDir& dir)
{
  return "rig --mesh '" + dir.file("neutral.obj").string() + "' --shapes '" + dir.file("shapes").string() + "'";
}

TEST(RigCli, ConvertsAnObjFolderRigToAGlbThatBindsDeformsAndSolvesAlike)
{
  test::TempDir dir;
  writeSmallRig(dir);
  const std::string glb = dir.file("rig.glb").string();
  const Outcome run = mocap(rigArguments(dir) + " -o '" + glb + "' --json", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const JsonValue json = parseJson(run.out, "rig --json");
  EXPECT_EQ(json.find("vertices", "rig")->number("vertices"), 468.0);
  EXPECT_EQ(json.find("triangles", "rig")->number("triangles"), 898.0);
  std::vector<std::string> names;
  for (const JsonValue& name : json.find("shapes", "rig")->array("shapes"))
    names.push_back(name.string("shape"));
  EXPECT_EQ(names, (std::vector<std::string>{"browInnerUp", "jawOpen", "mouthSmile_L"}));
  EXPECT_GT(json.find("moved_vertices", "rig")->number("moved_vertices"), 30.0);
  EXPECT_EQ(json.find("bytes", "rig")->number("bytes"), static_cast<double>(std::filesystem::file_size(glb)));

  const std::string fromFolder = dir.file("folder.csv").string(), fromGlb = dir.file("glb.csv").string();
  ASSERT_EQ(mocap(solveArguments(dir) + " --leave-out 0 -o '" + fromFolder + "'", dir).exitCode, 0);
  const Outcome solved = mocap("solve --mesh '" + glb + "' --binding '" +
                                   test::dataFile("../../resources/sample/Facial-Sing.binding.json").string() +
                                   "' --take " + sample() + " " + kStabilize + " --leave-out 0 -o '" + fromGlb + "'",
                               dir);
  ASSERT_EQ(solved.exitCode, 0) << solved.err;
  EXPECT_EQ(csvLines(readFileBytes(fromGlb))[0], csvLines(readFileBytes(fromFolder))[0]);
  const std::vector<double> folderWeights = csvWeights(readFileBytes(fromFolder));
  const std::vector<double> glbWeights = csvWeights(readFileBytes(fromGlb));
  ASSERT_EQ(folderWeights.size(), 3000u * 3u);
  ASSERT_EQ(glbWeights.size(), folderWeights.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < glbWeights.size(); ++i)
    largest = std::max(largest, std::abs(glbWeights[i] - folderWeights[i]));
  EXPECT_LT(largest, 1e-4) << "the GLB holds the rig as float32, nothing else differs";

  // bind and deform read the GLB's neutral as a mesh.
  const std::string binding = dir.file("bind.json").string();
  const Outcome bound = mocap("bind --mesh '" + glb + "' --take " + sample() + " " + kStabilize + " --markers " +
                                  faceMarkers() + " -o '" + binding + "'",
                              dir);
  ASSERT_EQ(bound.exitCode, 0) << bound.err;
  EXPECT_NE(bound.out.find("bound 31 markers"), std::string::npos) << bound.out;
  const Outcome deformed = mocap("deform --mesh '" + glb + "' --binding '" + binding + "' --take " + sample() + " " +
                                     kStabilize + " --frames 1:20 --leave-out 0 -o '" + dir.file("d.pc2").string() + "'",
                                 dir);
  ASSERT_EQ(deformed.exitCode, 0) << deformed.err;
  EXPECT_EQ(readPc2(dir.file("d.pc2")).samples.at(0).rows(), 468);
}

TEST(RigCli, KeepsAVertexRangeAndTheShapesAskedFor)
{
  test::TempDir dir;
  writeSmallRig(dir);
  const std::string glb = dir.file("crop.glb").string();
  const Outcome run = mocap(rigArguments(dir) + " --only jawOpen,browInnerUp --vertices 100:299 -o '" + glb + "' --json", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const Mesh face = readObj(dir.file("neutral.obj"));
  std::size_t inside = 0;
  for (const MeshFace& f : face.faces)
    inside += std::all_of(f.vertices.begin(), f.vertices.end(), [](Eigen::Index v) { return v >= 100 && v <= 299; });
  const JsonValue json = parseJson(run.out, "rig --json");
  EXPECT_EQ(json.find("vertices", "rig")->number("vertices"), 200.0);
  EXPECT_EQ(json.find("triangles", "rig")->number("triangles"), static_cast<double>(inside));
  const BlendshapeRig rig = readGltfRig(glb);
  EXPECT_EQ(rig.shapeNames(), (std::vector<std::string>{"jawOpen", "browInnerUp"}));
  EXPECT_EQ(rig.neutral.vertices.row(0), face.vertices.row(100).cast<float>().cast<double>());
  // --tolerance drops the entries that move no axis beyond it.
  const Outcome pruned = mocap(rigArguments(dir) + " --tolerance 0.3 -o '" + dir.file("pruned.glb").string() + "' --json", dir);
  ASSERT_EQ(pruned.exitCode, 0) << pruned.err;
  const BlendshapeRig all = readGltfRig(dir.file("pruned.glb"));
  for (const SparseShape& shape : all.shapes)
    for (Eigen::Index i = 0; i < shape.size(); ++i)
      EXPECT_GT(shape.deltas.row(i).cwiseAbs().maxCoeff(), 0.3);
  EXPECT_LT(parseJson(pruned.out, "rig").find("moved_vertices", "rig")->number("moved"),
            parseJson(mocap(rigArguments(dir) + " -o '" + dir.file("all.glb").string() + "' --json", dir).out, "rig")
                .find("moved_vertices", "rig")
                ->number("moved"));
}

TEST(RigCli, BadRangesOutputsAndShapeFoldersGiveClearErrors)
{
  test::TempDir dir;
  writeSmallRig(dir);
  const std::string glb = dir.file("rig.glb").string(), out = " -o '" + dir.file("x.glb").string() + "'";
  ASSERT_EQ(mocap(rigArguments(dir) + " -o '" + glb + "'", dir).exitCode, 0);
  const auto expectError = [&](const std::string& arguments, int exitCode, const std::string& fragment) {
    const Outcome run = mocap(arguments, dir);
    EXPECT_EQ(run.exitCode, exitCode) << arguments;
    EXPECT_NE(run.err.find(fragment), std::string::npos) << run.err;
  };
  expectError("rig --mesh '" + glb + "' --shapes '" + dir.file("shapes").string() + "'" + out, 2,
              "--shapes is not used with a glTF rig");
  expectError("rig --mesh '" + dir.file("neutral.obj").string() + "'" + out, 2, "--shapes DIR is needed");
  expectError(rigArguments(dir) + " --vertices 5:2" + out, 2, "--vertices needs FIRST:LAST vertex indices of the mesh (0…467)");
  expectError(rigArguments(dir) + " --vertices 0:468" + out, 2, "not '0:468'");
  expectError(rigArguments(dir) + " --vertices 7-9" + out, 2, "not '7-9'");
  expectError(rigArguments(dir) + " --vertices 10:20x" + out, 2, "not '10:20x': LAST '20x' is not a whole number");
  expectError(rigArguments(dir) + " --vertices 10x:20" + out, 2, "not '10x:20': FIRST '10x' is not a whole number");
  expectError(rigArguments(dir) + " --vertices=-3:5" + out, 2, "not '-3:5': FIRST -3 is less than 0");
  expectError(rigArguments(dir) + " --vertices 0:99999999999999999999" + out, 2, "does not fit a 64-bit whole number");
  expectError(rigArguments(dir) + " --vertices 10:" + out, 2, "not '10:': LAST is empty");
  expectError(rigArguments(dir) + " --vertices 7:7" + out, 2, "no face lies wholly inside vertices 7…7");
  expectError(rigArguments(dir) + " --only jawOpen,smile" + out, 2, "has no smile.obj");
  expectError(rigArguments(dir) + " -o '" + dir.file("rig.obj").string() + "'", 2, "-o must be a .glb file");
  writeFileAtomically(dir.file("junk.glb"), std::string("glTF") + std::string(40, '\0'));
  expectError("rig --mesh '" + dir.file("junk.glb").string() + "'" + out, 1, "junk.glb: GLB version 0");
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.glb")));
}

TEST(RigCli, TheBundledIctRigLoadsAndSolvesTheBundledTake)
{
  const std::filesystem::path sampleDir = checkout::sampleDir();
  const BlendshapeRig rig = readGltfRig(sampleDir / "ict_face_rig.glb");
  EXPECT_EQ(rig.neutral.vertexCount(), 9409);
  EXPECT_EQ(rig.neutral.triangles().size(), 18460u);  // ICT's 9230 face quads
  ASSERT_EQ(rig.shapeCount(), 53);
  EXPECT_EQ(rig.shapes.front().name, "browDown_L");
  EXPECT_EQ(rig.shapes[26].name, "jawOpen");
  EXPECT_EQ(rig.shapes.back().name, "noseSneer_R");

  test::TempDir dir;
  const Outcome run = mocap("solve --mesh '" + (sampleDir / "ict_face_rig.glb").string() + "' --binding '" +
                                (sampleDir / "Facial-Sing.ict_face_rig.binding.json").string() + "' --take " + sample() +
                                " " + kStabilize + " -o '" + dir.file("w.csv").string() + "' --json",
                            dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const JsonValue json = parseJson(run.out, "solve --json");
  EXPECT_EQ(json.find("shapes", "solve")->number("shapes"), 53.0);
  EXPECT_EQ(json.find("markers", "solve")->number("markers"), 31.0);
  EXPECT_EQ(json.find("held_frames", "solve")->number("held"), 0.0);
  // Measured: 2.28 mm mean, 4.36 mm p95; leave-out 1.90 mm (the bound points' residual is 2.45 mm mean).
  const JsonValue& residual = *json.find("residual_mm", "solve");
  EXPECT_LT(residual.find("mean", "residual")->number("mean"), 2.5);
  EXPECT_LT(residual.find("p95", "residual")->number("p95"), 5.0);
  const double leaveOut = json.find("leave_out_error_mm", "solve")->number("leave_out");
  EXPECT_LT(leaveOut, 2.2);
  EXPECT_LT(leaveOut, json.find("leave_out", "solve")->find("rest_error_mm", "leave_out")->number("rest"));
  EXPECT_EQ(csvLines(readFileBytes(dir.file("w.csv"))).size(), 3001u);
}

// The sample names its head-mounted markers root-1…6: a solve without --stabilize says so and
// names the option to pass (the CLI guesses nothing, so it does not stabilize by itself).
TEST(SolveCli, WithoutStabilizeOnATakeWithHeadMarkersSaysWhichToPass)
{
  test::TempDir dir;
  writeSmallRig(dir);
  std::string arguments = solveArguments(dir);
  arguments.erase(arguments.find(kStabilize));
  const std::string curves = dir.file("weights.csv").string();
  const Outcome json = mocap(arguments + " --leave-out 0 -o '" + curves + "' --json", dir);
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const JsonValue parsed = parseJson(json.out, "solve --json");
  const std::vector<JsonValue>& notes = parsed.find("notes", "solve")->array("notes");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].string("note").find("--stabilize root-1,root-2,root-3,root-4,root-5,root-6"), std::string::npos)
      << notes[0].string("note");
  const Outcome text = mocap(arguments + " --leave-out 0 -o '" + curves + "'", dir);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("note: the take names head-mounted markers"), std::string::npos) << text.out;
}

TEST(SolveCli, WritesTheRigWithItsAnimatedWeightsAsFbx)
{
  test::TempDir dir;
  writeSmallRig(dir);
  const std::string fbx = dir.file("solved.fbx").string(), csv = dir.file("solved.csv").string();
  const Outcome run = mocap(solveArguments(dir) + " --leave-out 0 --up z --units mm -o '" + fbx + "'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  ASSERT_EQ(mocap(solveArguments(dir) + " --leave-out 0 -o '" + csv + "'", dir).exitCode, 0);
  const std::vector<test::FbxTestNode> top = test::readFbxForTest(readFileBytes(fbx));
  std::map<std::int64_t, const test::FbxTestNode*> objects;
  std::vector<std::string> channels;
  for (const test::FbxTestNode& object : test::fbxNode(top, "Objects").children) {
    objects[object.properties.at(0).integer] = &object;
    if (object.properties.at(2).text == "BlendShapeChannel")
      channels.push_back(object.properties.at(1).text.substr(0, object.properties.at(1).text.find('\0')));
  }
  const std::string header = readFileBytes(csv).substr(0, readFileBytes(csv).find('\n'));
  EXPECT_EQ("Frame,Time," + channels.at(0) + "," + channels.at(1) + "," + channels.at(2), header)
      << "the channels are the rig's shapes, named and ordered as the weight CSV's columns";
  // Each DeformPercent curve, in channel order, against the CSV's columns.
  std::vector<std::vector<double>> curves;
  for (const test::FbxTestNode& c : test::fbxNode(top, "Connections").children)
    if (c.properties.size() == 4 && c.properties[3].text == "d|DeformPercent")
      curves.push_back(objects.at(c.properties[1].integer)->at("KeyValueFloat").properties.at(0).numbers);
  const std::vector<double> weights = csvWeights(readFileBytes(csv));
  ASSERT_EQ(curves.size(), 3u);
  ASSERT_EQ(weights.size(), 3000u * 3u);
  double largest = 0.0;
  for (std::size_t s = 0; s < 3; ++s) {
    ASSERT_EQ(curves[s].size(), 3000u);
    for (std::size_t f = 0; f < 3000; ++f)
      largest = std::max(largest, std::abs(curves[s][f] / 100.0 - weights[3 * f + s]));
  }
  EXPECT_LT(largest, 1e-4);
  for (const test::FbxTestNode& p : test::fbxNode(top, "GlobalSettings").at("Properties70").children) {
    if (p.properties.at(0).text == "UpAxis") {
      EXPECT_EQ(p.properties.at(4).integer, 2);
    }
    if (p.properties.at(0).text == "UnitScaleFactor") {
      EXPECT_EQ(p.properties.at(4).number, 0.1);
    }
  }

  // --up and --units belong to FBX output; an unwritable FBX is a clear error.
  Outcome bad = mocap(solveArguments(dir) + " --up z -o '" + csv + "'", dir);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find(".fbx output only"), std::string::npos) << bad.err;
  EXPECT_EQ(mocap(solveArguments(dir) + " --units m -o '" + fbx + "'", dir).exitCode, 2);
  bad = mocap(solveArguments(dir) + " --leave-out 0 -o '" + fbx + "/x.fbx'", dir);
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find("x.fbx"), std::string::npos) << bad.err;
}

TEST(SolveCli, MapsTheWeightsByAShippedNameOrAFileForEveryWriter)
{
  test::TempDir dir;
  writeSmallRig(dir);
  const std::string quick = solveArguments(dir) + " --method ridge --leave-out 0";
  const std::string plain = dir.file("plain.csv").string(), mapped = dir.file("mapped.csv").string();
  writeFileAtomically(dir.file("map.json"), R"({"format": "mocap retarget map", "version": 1,
  "channels": [
    {"name": "Smile", "sources": [{"shape": "mouthSmile_L", "gain": 2.0}], "max": 1.0},
    {"name": "Jaw", "sources": [{"shape": "jawOpen"}]}
  ]}
)");
  const std::string map = " --map '" + dir.file("map.json").string() + "'";
  ASSERT_EQ(mocap(quick + " -o '" + plain + "'", dir).exitCode, 0);
  const Outcome run = mocap(quick + map + " -o '" + mapped + "'", dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(csvLines(readFileBytes(mapped)).at(0), "Frame,Time,Smile,Jaw");
  const std::vector<double> before = csvWeights(readFileBytes(plain)), after = csvWeights(readFileBytes(mapped));
  ASSERT_EQ(after.size(), 3000u * 2u);
  double largest = 0.0, smile = 0.0;
  for (std::size_t f = 0; f < 3000; ++f) {
    largest = std::max(largest, std::abs(after[2 * f] - std::min(1.0, 2.0 * before[3 * f + 2])));
    largest = std::max(largest, std::abs(after[2 * f + 1] - before[3 * f + 1]));
    smile = std::max(smile, after[2 * f]);
  }
  EXPECT_LT(largest, 1e-12);
  EXPECT_GT(smile, 0.1);
  // The rig files carry the map's channels as their shapes.
  const std::string glb = dir.file("mapped.glb").string(), fbx = dir.file("mapped.fbx").string();
  ASSERT_EQ(mocap(quick + map + " -o '" + glb + "'", dir).exitCode, 0);
  EXPECT_EQ(readGltfRig(glb).shapeNames(), (std::vector<std::string>{"Smile", "Jaw"}));
  ASSERT_EQ(mocap(quick + map + " -o '" + fbx + "'", dir).exitCode, 0);
  std::vector<std::string> channels;
  const std::vector<test::FbxTestNode> top = test::readFbxForTest(readFileBytes(fbx));
  for (const test::FbxTestNode& object : test::fbxNode(top, "Objects").children)
    if (object.properties.at(2).text == "BlendShapeChannel")
      channels.push_back(object.properties.at(1).text.substr(0, object.properties.at(1).text.find('\0')));
  EXPECT_EQ(channels, (std::vector<std::string>{"Smile", "Jaw"}));

  // Errors name the map's line and write nothing: a channel Live Link Face does not have, a shipped
  // map taking shapes this rig lacks, a map that is not shipped, a map for a point cache.
  const std::string live = dir.file("live.csv").string();
  Outcome bad = mocap(quick + map + " --format livelink -o '" + live + "'", dir);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("channel 'Smile' (line 3) is not one of Live Link Face's 52 curves"), std::string::npos) << bad.err;
  bad = mocap(quick + " --map ict_to_arkit -o '" + live + "'", dir);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("channel 'EyeBlinkLeft' (line 5) takes 'eyeBlink_L', a shape the rig does not have"),
            std::string::npos)
      << bad.err;
  EXPECT_FALSE(std::filesystem::exists(live));
  bad = mocap(quick + " --map ict_to_unreal -o '" + live + "'", dir);
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find("neither a shipped map (ict_to_arkit, arkit_to_ict, ict_identity)"), std::string::npos) << bad.err;
  EXPECT_EQ(mocap(quick + map + " -o '" + dir.file("x.pc2").string() + "'", dir).exitCode, 2);
  EXPECT_EQ(mocap(quick + " --format livelink -o '" + glb + "'", dir).exitCode, 2) << "--format is the CSV's";
  EXPECT_FALSE(std::filesystem::exists(live));
}

// `mocap actor` on the sample (its first frame as the neutral, the take itself as the range of
// motion) and `mocap solve --actor`; bad input is refused with nothing written.
TEST(ActorCli, WritesAProfileThatSolveUsesAndRefusesBadInput)
{
  test::TempDir dir;
  const std::filesystem::path sampleDir = checkout::sampleDir();
  const std::string rig = " --rig '" + (sampleDir / "ict_face_rig.glb").string() + "'";
  const std::string binding = " --binding '" + (sampleDir / "Facial-Sing.ict_face_rig.binding.json").string() + "'";
  const std::string take = test::sampleTake().string();
  const std::string profile = dir.file("actor.json").string();
  const Outcome made = mocap("actor" + rig + binding + " --neutral '" + take + ":1' --rom '" + take + "' " +
                                 kStabilize + " -o '" + profile + "' --json",
                             dir);
  ASSERT_EQ(made.exitCode, 0) << made.err;
  const JsonValue json = parseJson(made.out, "actor --json");
  ASSERT_EQ(json.find("shapes", "actor")->array("shapes").size(), 53u);
  EXPECT_EQ(json.find("markers", "actor")->number("markers"), 31.0);
  EXPECT_NE(readFileBytes(profile).find("\"format\": \"mocap actor profile\""), std::string::npos);

  const Outcome solved = mocap("solve --mesh '" + (sampleDir / "ict_face_rig.glb").string() + "'" + binding +
                                   " --take '" + take + "' " + kStabilize + " --actor '" + profile +
                                   "' --method bvls -o '" + dir.file("w.csv").string() + "' --json",
                               dir);
  ASSERT_EQ(solved.exitCode, 0) << solved.err;
  const JsonValue solve = parseJson(solved.out, "solve --json");
  EXPECT_EQ(solve.find("actor", "solve")->string("actor"), "actor");
  EXPECT_TRUE(solve.find("neutral_frame", "solve")->isNull());

  const Outcome badFrame = mocap("actor" + rig + binding + " --neutral '" + take + ":x' -o '" + profile + "'", dir);
  EXPECT_EQ(badFrame.exitCode, 2);
  EXPECT_NE(badFrame.err.find("not a frame number"), std::string::npos) << badFrame.err;
  const std::string unwritable = dir.file("no/such/folder/actor.json").string();
  const Outcome cannotWrite = mocap("actor" + rig + binding + " --neutral '" + take + ":1' -o '" + unwritable + "'", dir);
  EXPECT_EQ(cannotWrite.exitCode, 1);
  EXPECT_FALSE(std::filesystem::exists(dir.file("no")));
  const Outcome outside = mocap("actor" + rig + binding + " --neutral '" + take + ":999999' -o '" + profile + "'", dir);
  EXPECT_EQ(outside.exitCode, 2);  // invalid input, as a bad --neutral frame of solve
  EXPECT_NE(outside.err.find("outside the take"), std::string::npos) << outside.err;
}

} // namespace
} // namespace mocap
