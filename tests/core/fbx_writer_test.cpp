// The binary FBX writer: the node and property encoding, the markers as animated nulls and the
// solved rig as a skinned mesh with blend-shape channels and DeformPercent curves, all read back
// with a small reader of the tests' own (fbx_test_reader.h).
#include "fbx_test_reader.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/fbx_binary.h"
#include "mocap/io/fbx_writer.h"
#include "mocap/io/take_io.h"

#include <gtest/gtest.h>

#include <map>

namespace mocap {
namespace {

using test::FbxTestNode;

/// Objects by id and the connections of a file read back.
struct FbxScene
{
  std::vector<FbxTestNode> top;
  std::map<std::int64_t, const FbxTestNode*> objects;
  struct Link
  {
    std::string kind;
    std::int64_t child = 0, parent = 0;
    std::string property;
  };
  std::vector<Link> links;

  explicit FbxScene(const std::string& bytes) : top(test::readFbxForTest(bytes))
  {
    for (const FbxTestNode& object : test::fbxNode(top, "Objects").children)
      objects[object.properties.at(0).integer] = &object;
    for (const FbxTestNode& c : test::fbxNode(top, "Connections").children)
      links.push_back({c.properties.at(0).text, c.properties.at(1).integer, c.properties.at(2).integer,
                       c.properties.size() > 3 ? c.properties[3].text : ""});
  }

  /// The objects of `kind` whose subtype is `subtype`, in file order.
  std::vector<const FbxTestNode*> ofKind(std::string_view kind, std::string_view subtype) const
  {
    std::vector<const FbxTestNode*> found;
    for (const FbxTestNode& object : test::fbxNode(top, "Objects").children)
      if (object.name == kind && object.properties.at(2).text == subtype)
        found.push_back(&object);
    return found;
  }

  /// The objects that `parent` is connected from with `kind` (and `property` for OP).
  std::vector<const FbxTestNode*> children(std::int64_t parent, std::string_view kind = "OO",
                                           std::string_view property = "") const
  {
    std::vector<const FbxTestNode*> found;
    for (const Link& link : links)
      if (link.parent == parent && link.kind == kind && link.property == property)
        found.push_back(objects.at(link.child));
    return found;
  }

  /// The one object connected from `parent` through property `property`.
  const FbxTestNode& driver(std::int64_t parent, std::string_view property) const
  {
    const std::vector<const FbxTestNode*> found = children(parent, "OP", property);
    if (found.size() != 1)
      throw std::runtime_error(std::to_string(found.size()) + " drivers of " + std::string(property));
    return *found.front();
  }

  /// A GlobalSettings property's first value.
  const test::FbxProperty& global(std::string_view name) const
  {
    for (const FbxTestNode& p : test::fbxNode(top, "GlobalSettings").at("Properties70").children)
      if (p.properties.at(0).text == name)
        return p.properties.at(4);
    throw std::runtime_error("no global setting " + std::string(name));
  }
};

std::string objectName(const FbxTestNode& object)
{
  const std::string& text = object.properties.at(1).text;
  return text.substr(0, text.find(std::string_view("\0\1", 2)));
}

std::int64_t idOf(const FbxTestNode& object)
{
  return object.properties.at(0).integer;
}

/// The key values of the curve connected to curve node `node` as `channel`.
std::vector<double> curveValues(const FbxScene& scene, const FbxTestNode& node, std::string_view channel)
{
  return scene.driver(idOf(node), channel).at("KeyValueFloat").properties.at(0).numbers;
}

// ---- encoding

TEST(FbxBinary, EncodesEveryPropertyTypeNestedNodesNullRecordsAndTheFooter)
{
  FbxNode root("Root");
  root.addBool(true).addInt16(-7).addInt32(123456).addInt64(-(1LL << 40)).addFloat(1.5F).addDouble(-2.25);
  root.addString(std::string("a\0\1b", 4)).addRaw("xyz");
  root.addFloats({1.0F, -2.0F}).addDoubles({0.5}).addInt32s({-1, 2, 3}).addInt64s({1LL << 50}).addBools({true, false});
  root.child("Empty");
  root.child("Leaf").addInt32(9);
  const FbxNode second("Second");
  const std::string bytes = fbxBinary({&root, &second});

  test::FbxTestReader reader(bytes);
  const std::vector<FbxTestNode> top = reader.read();
  EXPECT_EQ(reader.version, 7400u);
  ASSERT_EQ(top.size(), 2u);
  const FbxTestNode& r = top[0];
  EXPECT_EQ(r.name, "Root");
  ASSERT_EQ(r.properties.size(), 13u);
  EXPECT_EQ(std::string(1, r.properties[0].type) + r.properties[1].type + r.properties[2].type + r.properties[3].type,
            "CYIL");
  EXPECT_EQ(r.properties[0].integer, 1);
  EXPECT_EQ(r.properties[1].integer, -7);
  EXPECT_EQ(r.properties[2].integer, 123456);
  EXPECT_EQ(r.properties[3].integer, -(1LL << 40));
  EXPECT_EQ(r.properties[4].number, 1.5);
  EXPECT_EQ(r.properties[5].number, -2.25);
  EXPECT_EQ(r.properties[6].text, std::string("a\0\1b", 4));
  EXPECT_EQ(r.properties[7].type, 'R');
  EXPECT_EQ(r.properties[7].text, "xyz");
  EXPECT_EQ(r.properties[8].numbers, (std::vector<double>{1.0, -2.0}));
  EXPECT_EQ(r.properties[9].numbers, (std::vector<double>{0.5}));
  EXPECT_EQ(r.properties[10].integers, (std::vector<std::int64_t>{-1, 2, 3}));
  EXPECT_EQ(r.properties[11].integers, (std::vector<std::int64_t>{1LL << 50}));
  EXPECT_EQ(r.properties[12].integers, (std::vector<std::int64_t>{1, 0}));
  ASSERT_EQ(r.children.size(), 2u);
  EXPECT_EQ(r.children[0].name, "Empty");
  EXPECT_EQ(r.children[1].properties.at(0).integer, 9);
  EXPECT_EQ(top[1].name, "Second");

  // Footer: the fixed id right after the closing null record, then the version and the magic.
  EXPECT_EQ(static_cast<unsigned char>(bytes[reader.footerOffset]), 0xfa);
  EXPECT_EQ((bytes.size() - 140) % 16, 0u) << "the footer pads to 16, then 4 + 120 + 16 bytes";
  std::uint32_t version = 0;
  std::memcpy(&version, bytes.data() + bytes.size() - 140, 4);
  EXPECT_EQ(version, 7400u);
  EXPECT_EQ(static_cast<unsigned char>(bytes.back()), 0x0b);
}

TEST(FbxBinary, RejectsANodeNameLongerThan255Bytes)
{
  const FbxNode node(std::string(256, 'n'));
  EXPECT_THROW((void)fbxBinary({&node}), InvalidArgument);
}

// ---- markers

/// Two markers and a model output over 5 frames at 100 Hz in mm: marker "b" has a gap at frames
/// 1–2 and "never" is never valid.
Take gappedTake()
{
  Take take({"a", "b", "never", "angle"}, 5, 100.0);
  for (Eigen::Index f = 0; f < 5; ++f) {
    const auto t = static_cast<double>(f);
    take.setPosition(f, 0, Eigen::Vector3d(1000.0 + t, -20.5 * t, 1234.567));
    take.setPosition(f, 1, Eigen::Vector3d(t, 2.0 * t, 3.0 * t));
    take.setPosition(f, 3, Eigen::Vector3d(90.0, 0.0, 0.0));
    take.valid()(f, 0) = true;
    take.valid()(f, 1) = f < 1 || f > 2;
    take.valid()(f, 3) = true;
  }
  take.setPointType(3, PointType::Angle);
  return take;
}

const FbxTestNode& modelNamed(const FbxScene& scene, std::string_view name)
{
  for (const FbxTestNode* model : scene.ofKind("Model", "Null"))
    if (objectName(*model) == name)
      return *model;
  throw std::runtime_error("no null " + std::string(name));
}

TEST(FbxWriter, WritesEachMarkerAsAnAnimatedNullUnderOneRoot)
{
  const Take take = gappedTake();
  const FbxScene scene(markersFbx(take, FbxUpAxis::Z));
  const std::vector<const FbxTestNode*> nulls = scene.ofKind("Model", "Null");
  ASSERT_EQ(nulls.size(), 4u) << "the root and three markers; the angle is left out";
  const FbxTestNode& root = modelNamed(scene, "Markers");
  EXPECT_EQ(scene.children(idOf(root)).size(), 3u + 1u) << "three markers and the root's node attribute";
  EXPECT_THROW((void)modelNamed(scene, "angle"), std::runtime_error);

  const FbxTestNode& a = modelNamed(scene, "a");
  const FbxTestNode& translation = scene.driver(idOf(a), "Lcl Translation");
  EXPECT_EQ(objectName(translation), "T");
  const std::vector<double> x = curveValues(scene, translation, "d|X");
  const std::vector<double> y = curveValues(scene, translation, "d|Y");
  const std::vector<double> z = curveValues(scene, translation, "d|Z");
  ASSERT_EQ(x.size(), 5u);
  for (std::size_t f = 0; f < 5; ++f) {
    EXPECT_EQ(x[f], static_cast<double>(static_cast<float>(1000.0 + static_cast<double>(f))));
    EXPECT_EQ(y[f], static_cast<double>(static_cast<float>(-20.5 * static_cast<double>(f))));
    EXPECT_NEAR(z[f], 1234.567, 1e-4);
  }
  const std::vector<std::int64_t> times =
      scene.driver(idOf(translation), "d|X").at("KeyTime").properties.at(0).integers;
  EXPECT_EQ(times, (std::vector<std::int64_t>{0, 461861580, 923723160, 1385584740, 1847446320}));
  EXPECT_TRUE(scene.children(idOf(a), "OP", "Visibility").empty()) << "no gaps, no visibility curve";

  // Curve node → layer → stack.
  const std::vector<const FbxTestNode*> layers = scene.ofKind("AnimationLayer", "");
  ASSERT_EQ(layers.size(), 1u);
  EXPECT_EQ(scene.children(idOf(*layers[0])).size(), 3u) << "T of a, T and Visibility of b";
}

TEST(FbxWriter, HoldsAMarkerThroughItsGapsAndHidesIt)
{
  const FbxScene scene(markersFbx(gappedTake(), FbxUpAxis::Z));
  const FbxTestNode& b = modelNamed(scene, "b");
  const std::vector<double> x = curveValues(scene, scene.driver(idOf(b), "Lcl Translation"), "d|X");
  EXPECT_EQ(x, (std::vector<double>{0.0, 0.0, 3.0, 3.0, 4.0})) << "frame 1 holds frame 0, frame 2 holds frame 3";
  const FbxTestNode& visibility = scene.driver(idOf(b), "Visibility");
  EXPECT_EQ(curveValues(scene, visibility, "d|Visibility"), (std::vector<double>{1, 0, 0, 1, 1}));
  const FbxTestNode& curve = scene.driver(idOf(visibility), "d|Visibility");
  EXPECT_EQ(curve.at("KeyAttrFlags").properties.at(0).integers, (std::vector<std::int64_t>{2})) << "constant keys";

  const FbxTestNode& never = modelNamed(scene, "never");
  EXPECT_TRUE(scene.children(idOf(never), "OP", "Lcl Translation").empty()) << "no data, no keys";
  for (const FbxTestNode& p : never.at("Properties70").children) {
    if (p.properties.at(0).text == "Visibility") {
      EXPECT_EQ(p.properties.at(4).number, 0.0);
    }
  }
}

TEST(FbxWriter, DeclaresUnitsAxesRateAndTimeSpan)
{
  Take take = gappedTake();
  const FbxScene zUp(markersFbx(take, FbxUpAxis::Z));
  EXPECT_EQ(zUp.global("UpAxis").integer, 2);
  EXPECT_EQ(zUp.global("FrontAxis").integer, 1);
  EXPECT_EQ(zUp.global("FrontAxisSign").integer, -1);
  EXPECT_EQ(zUp.global("CoordAxis").integer, 0);
  EXPECT_DOUBLE_EQ(zUp.global("UnitScaleFactor").number, 0.1) << "mm is a tenth of FBX's cm";
  EXPECT_EQ(zUp.global("TimeMode").integer, 2) << "FBX's 100 Hz mode";
  EXPECT_DOUBLE_EQ(zUp.global("CustomFrameRate").number, 100.0);
  EXPECT_EQ(zUp.global("TimeSpanStart").integer, 0);
  EXPECT_EQ(zUp.global("TimeSpanStop").integer, 4 * kFbxTicksPerSecond / 100);
  const FbxTestNode& stack = *zUp.ofKind("AnimationStack", "").at(0);
  EXPECT_EQ(test::fbxNode(zUp.top, "Takes").at("Take").at("LocalTime").properties.at(1).integer,
            4 * kFbxTicksPerSecond / 100);
  EXPECT_EQ(objectName(stack), "Take 001");

  take.convertUnits(LengthUnit::Centimetre);
  take.setFrameRate(90.0);
  const FbxScene yUp(markersFbx(take, FbxUpAxis::Y));
  EXPECT_EQ(yUp.global("UpAxis").integer, 1);
  EXPECT_EQ(yUp.global("FrontAxis").integer, 2);
  EXPECT_EQ(yUp.global("FrontAxisSign").integer, 1);
  EXPECT_DOUBLE_EQ(yUp.global("UnitScaleFactor").number, 1.0);
  EXPECT_EQ(yUp.global("TimeMode").integer, 14) << "90 Hz is a custom rate";
  EXPECT_DOUBLE_EQ(yUp.global("CustomFrameRate").number, 90.0);
}

TEST(FbxWriter, TakeIoWritesFbxAndSaysModelOutputsAreLeftOut)
{
  EXPECT_EQ(formatFromPath("take.FBX"), TakeFormat::Fbx);
  EXPECT_NE(leftOutOnWriting(gappedTake(), TakeFormat::Fbx).find("the FBX file holds marker positions only"),
            std::string::npos);
  const test::TempDir dir;
  writeTake(gappedTake(), dir.file("take.fbx"));
  const FbxScene scene(readFileBytes(dir.file("take.fbx")));
  EXPECT_EQ(scene.global("UpAxis").integer, 2) << "takes are Z-up unless told otherwise";
  EXPECT_THROW((void)readTake(dir.file("take.fbx")), InvalidArgument);
}

// ---- the rig

/// A quad and a triangle sharing an edge, two shapes (one moves nothing).
BlendshapeRig smallRig()
{
  BlendshapeRig rig;
  rig.neutral.vertices.resize(5, 3);
  rig.neutral.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0.5, 0;
  rig.neutral.faces.push_back({{0, 1, 2, 3}, {}, {}});
  rig.neutral.faces.push_back({{1, 4, 2}, {}, {}});
  SparseShape jaw;
  jaw.name = "jawOpen";
  jaw.vertices = {1, 4};
  jaw.deltas.resize(2, 3);
  jaw.deltas << 0, -0.5, 0.25, 0.125, 0, 0;
  rig.shapes.push_back(jaw);
  SparseShape still;
  still.name = "mouthSmile_L";
  rig.shapes.push_back(still);
  return rig;
}

Eigen::MatrixXd smallWeights()
{
  Eigen::MatrixXd weights(3, 2);
  weights << 0.0, 1.0, 0.5, 0.25, 1.0, 0.0;
  return weights;
}

TEST(FbxWriter, WritesTheRigAsASkinnedMeshWithSparseShapes)
{
  const BlendshapeRig rig = smallRig();
  const FbxScene scene(rigFbx(rig, smallWeights(), 60.0, {}));
  const std::vector<const FbxTestNode*> meshes = scene.ofKind("Geometry", "Mesh");
  ASSERT_EQ(meshes.size(), 1u);
  const FbxTestNode& mesh = *meshes[0];
  EXPECT_EQ(mesh.at("Vertices").properties.at(0).numbers,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0.5, 0}));
  EXPECT_EQ(mesh.at("PolygonVertexIndex").properties.at(0).integers,
            (std::vector<std::int64_t>{0, 1, 2, -4, 1, 4, -3}));
  const std::vector<const FbxTestNode*> meshModels = scene.ofKind("Model", "Mesh");
  ASSERT_EQ(meshModels.size(), 1u);
  EXPECT_EQ(scene.children(idOf(*meshModels[0])), (std::vector<const FbxTestNode*>{&mesh}));

  // Skin: geometry ← skin ← cluster ← root bone, every vertex at weight 1.
  const std::vector<const FbxTestNode*> bones = scene.ofKind("Model", "LimbNode");
  ASSERT_EQ(bones.size(), 1u);
  const FbxTestNode& skin = *scene.ofKind("Deformer", "Skin").at(0);
  const FbxTestNode& cluster = *scene.ofKind("Deformer", "Cluster").at(0);
  EXPECT_EQ(cluster.at("Indexes").properties.at(0).integers, (std::vector<std::int64_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(cluster.at("Weights").properties.at(0).numbers, std::vector<double>(5, 1.0));
  EXPECT_EQ(scene.children(idOf(cluster)), (std::vector<const FbxTestNode*>{bones[0]}));
  EXPECT_EQ(scene.children(idOf(skin)), (std::vector<const FbxTestNode*>{&cluster}));
  EXPECT_EQ(scene.ofKind("Pose", "BindPose").size(), 1u);

  // Blend shape: geometry ← BlendShape ← channel ← Shape, names exactly the rig's.
  const FbxTestNode& blendShape = *scene.ofKind("Deformer", "BlendShape").at(0);
  const std::vector<const FbxTestNode*> onMesh = scene.children(idOf(mesh));
  EXPECT_EQ(onMesh, (std::vector<const FbxTestNode*>{&skin, &blendShape}));
  const std::vector<const FbxTestNode*> channels = scene.children(idOf(blendShape));
  ASSERT_EQ(channels.size(), 2u);
  for (std::size_t s = 0; s < 2; ++s) {
    EXPECT_EQ(objectName(*channels[s]), rig.shapes[s].name);
    const std::vector<const FbxTestNode*> shapes = scene.children(idOf(*channels[s]));
    ASSERT_EQ(shapes.size(), 1u);
    EXPECT_EQ(objectName(*shapes[0]), rig.shapes[s].name);
    EXPECT_EQ(shapes[0]->properties.at(2).text, "Shape");
  }
  const FbxTestNode& jaw = *scene.children(idOf(*channels[0]))[0];
  EXPECT_EQ(jaw.at("Indexes").properties.at(0).integers, (std::vector<std::int64_t>{1, 4}));
  EXPECT_EQ(jaw.at("Vertices").properties.at(0).numbers, (std::vector<double>{0, -0.5, 0.25, 0.125, 0, 0}));
  EXPECT_EQ(channels[0]->at("FullWeights").properties.at(0).numbers, (std::vector<double>{100.0, 100.0}));
  EXPECT_TRUE(scene.children(idOf(*channels[1]))[0]->at("Indexes").properties.at(0).integers.empty());
}

TEST(FbxWriter, AnimatesEachChannelsDeformPercentWithTheWeightTimes100)
{
  const Eigen::MatrixXd weights = smallWeights();
  const FbxScene scene(rigFbx(smallRig(), weights, 60.0, {FbxUpAxis::Z, LengthUnit::Millimetre, {}}));
  const FbxTestNode& blendShape = *scene.ofKind("Deformer", "BlendShape").at(0);
  const std::vector<const FbxTestNode*> channels = scene.children(idOf(blendShape));
  ASSERT_EQ(channels.size(), 2u);
  for (std::size_t s = 0; s < 2; ++s) {
    const FbxTestNode& node = scene.driver(idOf(*channels[s]), "DeformPercent");
    const std::vector<double> percent = curveValues(scene, node, "d|DeformPercent");
    ASSERT_EQ(percent.size(), 3u);
    for (std::size_t f = 0; f < 3; ++f)
      EXPECT_NEAR(percent[f], 100.0 * weights(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(s)), 1e-5);
  }
  EXPECT_EQ(scene.global("UpAxis").integer, 2);
  EXPECT_DOUBLE_EQ(scene.global("UnitScaleFactor").number, 0.1);
  EXPECT_EQ(scene.global("TimeMode").integer, 3) << "60 Hz";
  EXPECT_EQ(scene.global("TimeSpanStop").integer, 2 * kFbxTicksPerSecond / 60);

  const FbxScene still(rigFbx(smallRig(), Eigen::MatrixXd(0, 2), 60.0, {}));
  EXPECT_TRUE(still.ofKind("AnimationCurve", "").empty()) << "no weights, no curves";
}

TEST(FbxWriter, RejectsBadRigInputAndKeepsThePreviousFile)
{
  const BlendshapeRig rig = smallRig();
  EXPECT_THROW((void)rigFbx(rig, Eigen::MatrixXd::Zero(3, 3), 60.0, {}), InvalidArgument);
  Eigen::MatrixXd nan = smallWeights();
  nan(1, 1) = std::nan("");
  EXPECT_THROW((void)rigFbx(rig, nan, 60.0, {}), InvalidArgument);
  EXPECT_THROW((void)rigFbx(rig, smallWeights(), 0.0, {}), InvalidArgument);
  BlendshapeRig wrong = rig;
  wrong.shapes[0].vertices = {1, 9};
  EXPECT_THROW((void)rigFbx(wrong, smallWeights(), 60.0, {}), InvalidArgument);

  const test::TempDir dir;
  writeFileAtomically(dir.file("rig.fbx"), "previous");
  EXPECT_THROW(writeRigFbx(dir.file("rig.fbx"), wrong, smallWeights(), 60.0, {}), InvalidArgument);
  EXPECT_EQ(readFileBytes(dir.file("rig.fbx")), "previous");
  writeFileAtomically(dir.file("file"), "x");
  EXPECT_THROW(writeRigFbx(dir.file("file") / "rig.fbx", rig, smallWeights(), 60.0, {}), IoError);
}

// ---- key reduction

/// A curve's linear interpolation at `time` (KeyTime ticks), from its keys.
double interpolateKeys(const FbxTestNode& curve, std::int64_t time)
{
  const std::vector<std::int64_t> times = curve.at("KeyTime").properties.at(0).integers;
  const std::vector<double> values = curve.at("KeyValueFloat").properties.at(0).numbers;
  std::size_t k = 0;
  while (k + 2 < times.size() && times[k + 1] <= time)
    ++k;
  if (times.size() == 1 || time <= times[k])
    return values[k];
  const double t = static_cast<double>(time - times[k]) / static_cast<double>(times[k + 1] - times[k]);
  return values[k] + std::min(t, 1.0) * (values[k + 1] - values[k]);
}

Eigen::MatrixXd smoothWeights(Eigen::Index frames)
{
  Eigen::MatrixXd weights(frames, 2);
  for (Eigen::Index f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / 60.0;
    weights(f, 0) = 0.5 + 0.5 * std::sin(3.0 * t);
    weights(f, 1) = f < frames / 2 ? 0.0 : 0.25;  // a hold, a step, a hold
  }
  return weights;
}

TEST(FbxWriter, ReducesEachDeformPercentCurveWithinTheToleranceAndCountsTheKeys)
{
  const Eigen::MatrixXd weights = smoothWeights(300);
  KeyCount counted;
  FbxRigOptions options;
  options.keys = {0.01, &counted};
  const FbxScene scene(rigFbx(smallRig(), weights, 60.0, options));
  const std::vector<const FbxTestNode*> channels =
      scene.children(idOf(*scene.ofKind("Deformer", "BlendShape").at(0)));
  std::size_t keys = 0;
  for (std::size_t s = 0; s < 2; ++s) {
    const FbxTestNode& curve = scene.driver(idOf(scene.driver(idOf(*channels[s]), "DeformPercent")), "d|DeformPercent");
    keys += curve.at("KeyTime").properties.at(0).integers.size();
    for (Eigen::Index f = 0; f < weights.rows(); ++f)
      EXPECT_NEAR(interpolateKeys(curve, f * kFbxTicksPerSecond / 60), 100.0 * weights(f, static_cast<Eigen::Index>(s)),
                  1.0 + 1e-4)
          << "shape " << s << " frame " << f << ": within 0.01 weight units (1 percent)";
  }
  EXPECT_EQ(counted.before, 600);
  EXPECT_EQ(counted.after, static_cast<Eigen::Index>(keys));
  EXPECT_LT(keys, 60u) << "a smooth curve and a step keep few keys";
  EXPECT_GE(keys, 6u) << "the step's hold keeps both ends of each run";
  EXPECT_LE(counted.maxError, 0.01);
  EXPECT_GT(counted.maxError, 0.0);

  KeyCount exact;
  options.keys = {0.0, &exact};
  const FbxScene zero(rigFbx(smallRig(), weights, 60.0, options));
  const std::vector<const FbxTestNode*> zeroChannels =
      zero.children(idOf(*zero.ofKind("Deformer", "BlendShape").at(0)));
  const FbxTestNode& sine = zero.driver(idOf(zero.driver(idOf(*zeroChannels[0]), "DeformPercent")), "d|DeformPercent");
  for (Eigen::Index f = 0; f < weights.rows(); ++f)
    EXPECT_NEAR(interpolateKeys(sine, f * kFbxTicksPerSecond / 60), 100.0 * weights(f, 0), 1e-4)
        << "zero tolerance keeps every distinct value";
  EXPECT_LE(exact.maxError, 1e-12);

  options.keys = {-1.0, nullptr};
  EXPECT_THROW((void)rigFbx(smallRig(), weights, 60.0, options), InvalidArgument);
}

TEST(FbxWriter, ReducesMarkerCurvesOneByOneAndKeysVisibilityOnlyWhereItChanges)
{
  KeyCount counted;
  const FbxScene scene(markersFbx(gappedTake(), FbxUpAxis::Z, {0.5, &counted}));
  const FbxTestNode& a = modelNamed(scene, "a");
  const FbxTestNode& translation = scene.driver(idOf(a), "Lcl Translation");
  for (const char* axis : {"d|X", "d|Y", "d|Z"})
    EXPECT_EQ(scene.driver(idOf(translation), axis).at("KeyTime").properties.at(0).integers,
              (std::vector<std::int64_t>{0, 4 * kFbxTicksPerSecond / 100}))
        << axis << ": a straight line keeps its ends";
  const FbxTestNode& b = modelNamed(scene, "b");
  const FbxTestNode& bx = scene.driver(idOf(scene.driver(idOf(b), "Lcl Translation")), "d|X");
  EXPECT_EQ(bx.at("KeyValueFloat").properties.at(0).numbers, (std::vector<double>{0.0, 0.0, 3.0, 3.0, 4.0}))
      << "each held run keeps its first and last frame";
  const FbxTestNode& visibility = scene.driver(idOf(scene.driver(idOf(b), "Visibility")), "d|Visibility");
  EXPECT_EQ(visibility.at("KeyValueFloat").properties.at(0).numbers, (std::vector<double>{1, 0, 1, 1}));
  EXPECT_EQ(visibility.at("KeyTime").properties.at(0).integers,
            (std::vector<std::int64_t>{0, kFbxTicksPerSecond / 100, 3 * kFbxTicksPerSecond / 100,
                                       4 * kFbxTicksPerSecond / 100}));
  EXPECT_EQ(counted.before, 2 * 3 * 5) << "translation curves of a and b";
  EXPECT_EQ(counted.after, 3 * 2 + 3 * 5);
  EXPECT_LE(counted.maxError, 1e-9);
}

} // namespace
} // namespace mocap
