// `mocap bind`, `mocap deform` and `mocap solve` end to end on the bundled take and the MediaPipe face.
#include "../core/test_support.h"

#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/io/pc2_io.h"
#include "mocap/io/obj_io.h"
#include "mocap/io/ply_io.h"

#include <gtest/gtest.h>

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
  const std::string command = std::string("'") + MOCAP_CLI + "' " + arguments + " >'" +
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

  const std::string live = dir.file("live.csv").string();
  const Outcome liveRun = mocap(solveArguments(dir) + " --method bvls --format livelink --leave-out 0 -o '" + live + "'", dir);
  ASSERT_EQ(liveRun.exitCode, 0) << liveRun.err;
  const std::vector<std::string> liveLines = csvLines(readFileBytes(live));
  ASSERT_EQ(liveLines.size(), 3001u);
  EXPECT_EQ(liveLines[0], "Timecode,BlendShapeCount,browInnerUp,jawOpen,mouthSmile_L");
  EXPECT_EQ(liveLines[1].substr(0, 18), "00:00:00:00.000,3,");
  EXPECT_EQ(liveLines[2].substr(0, 18), "00:00:00:01.000,3,");
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

} // namespace
} // namespace mocap
