// `mocap convert REC.csv OUT.glb|OUT.fbx --rig RIG [--map MAP]`: a Live Link Face recording as weight
// curves on a rig, its timecode kept where the format has a start time; and its bad input.
#include "shell_run.h"

#include "../core/fbx_test_reader.h"
#include "../core/glb_model.h"
#include "../core/test_support.h"
#include "checkout_paths.h"

#include "mocap/base/file_io.h"
#include "mocap/io/gltf_rig_reader.h"
#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/live_link_face_map.h"

#include <gtest/gtest.h>

#include <cstring>

namespace mocap {
namespace {

std::filesystem::path liveLinkRecording()
{
  return test::dataFile("livelink_face/alex_rom_4_first200.csv");
}

std::filesystem::path bundledIctRig()
{
  return std::filesystem::path(checkout::sampleDir()) / "ict_face_rig.glb";
}

test::ShellResult liveLinkMocap(const std::string& arguments, const test::TempDir& dir)
{
  return test::runShell(test::shellQuote(std::string(checkout::cliProgram())) + " " + arguments, dir.path());
}

std::string convertRecording(const std::filesystem::path& in, const std::filesystem::path& out)
{
  return "convert " + test::shellQuote(in) + " " + test::shellQuote(out) + " --rig " + test::shellQuote(bundledIctRig());
}

/// The float accessor `index` of a GLB, read whole.
std::vector<float> glbFloats(const tinygltf::Model& model, int index)
{
  const tinygltf::Accessor& accessor = model.accessors.at(static_cast<std::size_t>(index));
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
  const std::size_t count = accessor.count * (accessor.type == TINYGLTF_TYPE_SCALAR ? 1u : 0u);
  std::vector<float> values(count);
  std::memcpy(values.data(),
              model.buffers.at(static_cast<std::size_t>(view.buffer)).data.data() + view.byteOffset + accessor.byteOffset,
              count * sizeof(float));
  return values;
}

TEST(LiveLinkCli, ARecordingBecomesTheIctRigsAnimation)
{
  test::TempDir dir;
  const std::filesystem::path glb = dir.file("alex.glb");
  const test::ShellResult run = liveLinkMocap(convertRecording(liveLinkRecording(), glb), dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("200 frames at 30 Hz from 16:55:51:38.453 onto 53 shapes"), std::string::npos) << run.out;
  const BlendshapeRig rig = readGltfRig(glb);
  EXPECT_EQ(rig.shapeNames(), readGltfRig(bundledIctRig()).shapeNames());

  // The animation holds the recording's values under the rig's names (arkit_to_ict: each split
  // ICT shape from its one ARKit curve), one key per row at the recording's 30 Hz.
  const LiveLinkFaceRecording recording = readLiveLinkFaceCsv(liveLinkRecording());
  const RetargetMap map = rigMapFromLiveLinkFace(rig.shapeNames());
  const Eigen::MatrixXd expected =
      mappedWeightsOnRig(map, applyRetargetMap(map, liveLinkFaceShapeNames(), recording.weights), rig.shapeNames());
  const tinygltf::Model model = test::glbModel(readFileBytes(glb));
  ASSERT_EQ(model.animations.size(), 1u);
  // glTF has no start time: the recording's start timecode is kept in the animation's extras.
  ASSERT_TRUE(model.animations[0].extras.Has("startSeconds"));
  EXPECT_NEAR(model.animations[0].extras.Get("startSeconds").GetNumberAsDouble(),
              liveLinkFaceSeconds("16:55:51:38.453"), 1e-9);
  const tinygltf::AnimationSampler& sampler = model.animations[0].samplers.at(0);
  const std::vector<float> times = glbFloats(model, sampler.input), values = glbFloats(model, sampler.output);
  ASSERT_EQ(times.size(), 200u);
  EXPECT_NEAR(times.back(), 199.0 / 30.0, 1e-5);
  ASSERT_EQ(values.size(), 200u * 53u);
  double largest = 0.0;
  for (Eigen::Index f = 0; f < 200; ++f)
    for (Eigen::Index s = 0; s < 53; ++s)
      largest = std::max(largest, std::abs(static_cast<double>(values[static_cast<std::size_t>(f * 53 + s)]) - expected(f, s)));
  EXPECT_LT(largest, 1e-7) << "float32 of the CSV's values";
  const auto jaw = static_cast<Eigen::Index>(*rig.shapeIndex("jawOpen"));
  EXPECT_GT(expected.maxCoeff(), 0.5) << "the range-of-motion take moves its curves";
  const auto jawCurve = static_cast<Eigen::Index>(
      std::find(liveLinkFaceShapeNames().begin(), liveLinkFaceShapeNames().end(), "JawOpen") - liveLinkFaceShapeNames().begin());
  EXPECT_EQ(expected.col(jaw), recording.weights.col(jawCurve));
}

TEST(LiveLinkCli, TheFbxKeepsTheRecordingsTimecodeAsItsStart)
{
  test::TempDir dir;
  const std::filesystem::path fbx = dir.file("alex.fbx");
  const test::ShellResult run = liveLinkMocap(convertRecording(liveLinkRecording(), fbx), dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::vector<test::FbxTestNode> top = test::readFbxForTest(readFileBytes(fbx));
  const double start = liveLinkFaceSeconds("16:55:51:38.453");
  std::size_t curves = 0;
  for (const test::FbxTestNode& object : test::fbxNode(top, "Objects").children)
    if (object.name == "AnimationCurve") {
      const std::vector<std::int64_t>& keys = object.at("KeyTime").properties.at(0).integers;
      ASSERT_EQ(keys.size(), 200u);
      EXPECT_NEAR(static_cast<double>(keys.front()) / 46186158000.0, start, 1e-6);
      EXPECT_NEAR(static_cast<double>(keys.back() - keys.front()) / 46186158000.0, 199.0 / 30.0, 1e-6);
      ++curves;
    }
  EXPECT_EQ(curves, 53u);
  for (const test::FbxTestNode& p : test::fbxNode(top, "GlobalSettings").at("Properties70").children) {
    if (p.properties.at(0).text == "TimeSpanStart") {
      EXPECT_NEAR(static_cast<double>(p.properties.at(4).integer) / 46186158000.0, start, 1e-6);
    }
  }
}

TEST(LiveLinkCli, BadRecordingsAndMapsAreClearErrorsAndWriteNothing)
{
  test::TempDir dir;
  const std::filesystem::path out = dir.file("out.glb");
  const std::string text = readFileBytes(liveLinkRecording());
  const std::size_t second = text.find('\n') + 1, third = text.find('\n', second) + 1;
  const auto expectError = [&](const std::string& arguments, int code, const std::string& message) {
    const test::ShellResult run = liveLinkMocap(arguments, dir);
    EXPECT_EQ(run.exitCode, code) << arguments << '\n' << run.err;
    EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << arguments;
  };
  // A row one value short (line 3), a timecode that is not HH:MM:SS:FF.mmm (line 2).
  writeFileAtomically(dir.file("short.csv"), text.substr(0, text.rfind(',', text.find('\n', third))) + "\n");
  expectError(convertRecording(dir.file("short.csv"), out), 1, "line 3: 62 fields where the header has 63");
  writeFileAtomically(dir.file("timecode.csv"), text.substr(0, second) + "16:55:51.38" + text.substr(text.find(',', second)));
  expectError(convertRecording(dir.file("timecode.csv"), out), 1, "line 2: Live Link Face: '16:55:51.38' is not a timecode");
  // A map by a name that is not shipped, one whose channel names a shape the rig lacks.
  expectError(convertRecording(liveLinkRecording(), out) + " --map arkit_to_metahuman", 1, "is neither a shipped map (ict_to_arkit");
  writeFileAtomically(dir.file("tongue.json"), R"({"format": "mocap retarget map", "version": 1,
  "channels": [
    {"name": "jawOpen", "sources": [{"shape": "JawOpen"}]},
    {"name": "tongueOut", "sources": [{"shape": "TongueOut"}]}
  ]}
)");
  expectError(convertRecording(liveLinkRecording(), out) + " --map " + test::shellQuote(dir.file("tongue.json")), 2,
              "channel 'tongueOut' (line 4) is not a shape of the rig");
  // A .csv IN is a recording: it needs the rig, and goes to a rig format.
  expectError("convert " + test::shellQuote(liveLinkRecording()) + " " + test::shellQuote(out), 2, "--rig RIG");
  expectError(convertRecording(liveLinkRecording(), dir.file("out.trc")), 2, "(.glb, .fbx)");
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.trc")));
  EXPECT_EQ(test::entryCount(dir.path()), 3u) << "only the three inputs written here";
}

} // namespace
} // namespace mocap
