// The maps between a rig's shapes and Live Link Face's 52 curves: the shipped maps compiled in,
// the defaults for ICT FaceKit and Apple's ARKit names, and a rig re-expressed under a map.
#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/live_link_face_map.h"
#include "mocap/io/retarget_map_io.h"
#include "mocap/io/shipped_retarget_maps.h"

#include "checkout_paths.h"
#include "error_text.h"
#include "test_support.h"

#include "mocap/base/error.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

using test::errorOf;

std::vector<std::string> ictShapeNames()
{
  std::vector<std::string> names;
  const RetargetMap identity = shippedRetargetMap("ict_identity").value();
  for (const RetargetChannel& channel : identity.channels)
    names.push_back(channel.name);
  return names;
}

Eigen::Index columnOf(const std::vector<std::string>& names, const std::string& name)
{
  const auto found = std::find(names.begin(), names.end(), name);
  EXPECT_NE(found, names.end()) << name;
  return found - names.begin();
}

TEST(ShippedRetargetMaps, AreCompiledInAsTheFilesSayAndSelectableByName)
{
  EXPECT_EQ(shippedRetargetMapNames(), (std::vector<std::string>{"ict_to_arkit", "arkit_to_ict", "ict_identity"}));
  const std::filesystem::path folder = std::filesystem::path(checkout::sourceDir()) / "resources" / "retarget";
  for (const std::string& name : shippedRetargetMapNames()) {
    const RetargetMap compiled = readRetargetMapByNameOrPath(name);
    EXPECT_EQ(retargetMapJson(compiled), retargetMapJson(readRetargetMap(folder / (name + ".json")))) << name;
  }
  EXPECT_EQ(ictShapeNames().size(), 53u);
  // A path reads the file; a name that is neither says which maps are shipped.
  EXPECT_EQ(readRetargetMapByNameOrPath((folder / "arkit_to_ict.json").string()).channels.size(), 53u);
  const std::string unknown = errorOf([] { (void)readRetargetMapByNameOrPath("ict_to_metahuman"); });
  EXPECT_NE(unknown.find("'ict_to_metahuman' is neither a shipped map (ict_to_arkit, arkit_to_ict, ict_identity)"),
            std::string::npos)
      << unknown;
  EXPECT_FALSE(shippedRetargetMap("nothing").has_value());
}

TEST(LiveLinkFaceMap, TheBundledIctRigGoesThroughTheShippedMapInTheAppsOrder)
{
  const std::vector<std::string> ict = ictShapeNames();
  const RetargetMap map = liveLinkFaceMapForRig(ict);
  Eigen::MatrixXd weights = Eigen::MatrixXd::Zero(1, static_cast<Eigen::Index>(ict.size()));
  weights(0, columnOf(ict, "browInnerUp_L")) = 1.0;
  weights(0, columnOf(ict, "browInnerUp_R")) = 0.5;
  weights(0, columnOf(ict, "mouthSmile_L")) = 0.25;
  const MappedWeights mapped = applyRetargetMap(map, ict, weights);
  EXPECT_EQ(mapped.names, liveLinkFaceShapeNames());
  EXPECT_DOUBLE_EQ(mapped.weights(0, columnOf(mapped.names, "BrowInnerUp")), 0.75);
  EXPECT_DOUBLE_EQ(mapped.weights(0, columnOf(mapped.names, "MouthSmileLeft")), 0.25);
  EXPECT_DOUBLE_EQ(mapped.weights(0, columnOf(mapped.names, "TongueOut")), 0.0);
}

TEST(LiveLinkFaceMap, ApplesArkitNamesAndTheAppsOwnFindTheirCurves)
{
  // Apple's names: ICT's, but browInnerUp and cheekPuff whole; a source the rig lacks counts 0.
  const std::vector<std::string> apple{"browInnerUp", "jawOpen", "mouthSmile_L"};
  const MappedWeights mapped = applyRetargetMap(liveLinkFaceMapForRig(apple), apple, Eigen::RowVector3d(0.5, 0.25, 1.0));
  EXPECT_DOUBLE_EQ(mapped.weights(0, columnOf(mapped.names, "BrowInnerUp")), 0.5);
  EXPECT_DOUBLE_EQ(mapped.weights(0, columnOf(mapped.names, "JawOpen")), 0.25);
  EXPECT_DOUBLE_EQ(mapped.weights(0, columnOf(mapped.names, "MouthSmileLeft")), 1.0);
  EXPECT_DOUBLE_EQ(mapped.weights(0, columnOf(mapped.names, "MouthSmileRight")), 0.0);
  // A rig named as the app names its curves maps by identity.
  const RetargetMap own = liveLinkFaceMapForRig({"JawOpen", "TongueOut"});
  ASSERT_EQ(own.channels.size(), 2u);
  EXPECT_EQ(own.channels[1].sources.at(0).shape, "TongueOut");
}

TEST(LiveLinkFaceMap, ARigNamedOtherwiseNeedsAMapOfItsOwn)
{
  const std::string forward = errorOf([] { (void)liveLinkFaceMapForRig({"jawOpen", "smile", "frown"}); });
  EXPECT_NE(forward.find("'smile', 'frown'"), std::string::npos) << forward;
  EXPECT_NE(forward.find("--map"), std::string::npos) << forward;
  const std::string back = errorOf([] { (void)rigMapFromLiveLinkFace({"jawOpen", "smile"}); });
  EXPECT_NE(back.find("'smile'"), std::string::npos) << back;
  // A map for the CSV must target the app's curves, one reading a recording take only them: both
  // errors name the channel's line.
  const RetargetMap map = parseRetargetMap(R"({"format": "mocap retarget map", "version": 1,
  "channels": [
    {"name": "JawOpen", "sources": [{"shape": "jawOpen"}]},
    {"name": "Smile", "sources": [{"shape": "smile"}]}
  ]})",
                                           "m.json");
  EXPECT_NE(errorOf([&] { checkLiveLinkFaceChannels(map); }).find("channel 'Smile' (line 4)"), std::string::npos);
  EXPECT_NE(errorOf([&] { checkLiveLinkFaceSources(map); }).find("channel 'JawOpen' (line 3) takes 'jawOpen'"),
            std::string::npos);
}

TEST(LiveLinkFaceMap, ARecordingGoesOntoTheIctRigAndBackUnchanged)
{
  const LiveLinkFaceRecording recording = readLiveLinkFaceCsv(test::dataFile("livelink_face/alex_rom_4_first200.csv"));
  const std::vector<std::string> ict = ictShapeNames();
  const Eigen::MatrixXd onRig = liveLinkFaceWeightsOnRig(recording.weights, ict, std::nullopt);  // rigMapFromLiveLinkFace
  ASSERT_EQ(onRig.cols(), 53);
  EXPECT_EQ(onRig, liveLinkFaceWeightsOnRig(recording.weights, ict, shippedRetargetMap("arkit_to_ict")));
  // A map that reads our shapes, not the recording's curves, is refused by its channel and line.
  EXPECT_NE(errorOf([&] { (void)liveLinkFaceWeightsOnRig(recording.weights, ict, shippedRetargetMap("ict_to_arkit")); })
                .find("which is not one of Live Link Face's 52 curves"),
            std::string::npos);
  EXPECT_EQ(onRig.col(columnOf(ict, "browInnerUp_L")), recording.weights.col(columnOf(liveLinkFaceShapeNames(), "BrowInnerUp")));
  const MappedWeights back = applyRetargetMap(liveLinkFaceMapForRig(ict), ict, onRig);
  Eigen::MatrixXd expected = recording.weights;
  expected.col(columnOf(liveLinkFaceShapeNames(), "TongueOut")).setZero();  // ICT FaceKit has no tongue
  EXPECT_LT((back.weights - expected).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_GT(recording.weights.maxCoeff(), 0.5) << "a range-of-motion take moves its curves";
}

TEST(RetargetedRig, PosesUnderTheMapsChannelsAsTheRigDoesUnderItsShapes)
{
  BlendshapeRig rig;
  rig.neutral.vertices = MeshVertices::Zero(4, 3);
  MeshVertices left = rig.neutral.vertices, right = rig.neutral.vertices;
  left.row(0) << 1.0, 0.0, 0.0;
  left.row(2) << 0.0, 1.0, 0.0;
  right.row(2) << 0.0, 0.0, 2.0;
  rig.shapes = {sparseShape("smile_L", rig.neutral.vertices, left, 1e-9),
                sparseShape("smile_R", rig.neutral.vertices, right, 1e-9)};
  RetargetMap map;
  map.channels.push_back({"Smile", {{"smile_L", 0.5}, {"smile_R", 0.5}}});
  map.channels.push_back({"Nothing", {}});
  const BlendshapeRig mapped = retargetedRig(map, rig);
  ASSERT_EQ(mapped.shapeNames(), (std::vector<std::string>{"Smile", "Nothing"}));
  EXPECT_EQ(mapped.shapes[0].vertices, (std::vector<Eigen::Index>{0, 2}));
  EXPECT_EQ(mapped.shapes[1].size(), 0);
  MeshVertices byRig, byMap;
  rig.evaluate(Eigen::Vector2d(0.5, 0.5), byRig);
  mapped.evaluate(Eigen::Vector2d(1.0, 0.0), byMap);
  EXPECT_TRUE(byMap.isApprox(byRig)) << byMap;
  map.channels[0].sources[1].shape = "frown";
  map.channels[0].line = 7;
  EXPECT_NE(errorOf([&] { (void)retargetedRig(map, rig); }).find("channel 'Smile' (line 7) takes 'frown'"),
            std::string::npos);
}

} // namespace
} // namespace mocap
