// The rig GLB: neutral mesh, sparse morph targets named in extras.targetNames, weight animation;
// read back with TinyGLTF's loader, an independent parser of what we wrote.
#include "face_mesh_fixture.h"
#include "glb_model.h"

#include "mocap/base/error.h"
#include "mocap/io/gltf_writer.h"

#include <gtest/gtest.h>


#include <cstring>

namespace mocap {
namespace {

BlendshapeRig twoShapeRig()
{
  const Mesh& face = test::mediaPipeFace();
  BlendshapeRig rig;
  rig.neutral = face;
  MeshVertices open = face.vertices;
  open.row(14) += Eigen::RowVector3d(0.0, -1.25, 0.5);
  open.row(17) += Eigen::RowVector3d(0.0, -0.75, 0.0);
  rig.shapes.push_back(sparseShape("jawOpen", face.vertices, open, 1e-9));
  rig.shapes.push_back(sparseShape("still", face.vertices, face.vertices, 1e-9));
  return rig;
}

template <typename T>
std::vector<T> accessorValues(const tinygltf::Model& model, int bufferView, std::size_t count)
{
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(bufferView)];
  std::vector<T> values(count);
  std::memcpy(values.data(), model.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset,
              count * sizeof(T));
  return values;
}

TEST(GltfWriter, WritesTheNeutralSparseTargetsTheirNamesAndTheWeightAnimation)
{
  const BlendshapeRig rig = twoShapeRig();
  Eigen::MatrixXd weights(4, 2);
  weights << 0.0, 0.0, 0.25, 1.0, 0.5, 0.125, 1.0, 0.0;
  const tinygltf::Model model = test::glbModel(rigGlb(rig, weights, 50.0));
  ASSERT_EQ(model.meshes.size(), 1u);
  const tinygltf::Mesh& mesh = model.meshes[0];
  const tinygltf::Primitive& primitive = mesh.primitives.at(0);
  EXPECT_EQ(model.accessors[static_cast<std::size_t>(primitive.attributes.at("POSITION"))].count, 468u);
  EXPECT_EQ(model.accessors[static_cast<std::size_t>(primitive.indices)].count,
            3 * rig.neutral.triangles().size());
  ASSERT_EQ(primitive.targets.size(), 2u);
  const tinygltf::Value& names = mesh.extras.Get("targetNames");
  ASSERT_EQ(names.ArrayLen(), 2u);
  EXPECT_EQ(names.Get(0).Get<std::string>(), "jawOpen");
  EXPECT_EQ(names.Get(1).Get<std::string>(), "still");

  const tinygltf::Accessor& open = model.accessors[static_cast<std::size_t>(primitive.targets[0].at("POSITION"))];
  ASSERT_TRUE(open.sparse.isSparse);
  ASSERT_EQ(open.sparse.count, 2);
  EXPECT_EQ(accessorValues<std::uint32_t>(model, open.sparse.indices.bufferView, 2), (std::vector<std::uint32_t>{14, 17}));
  EXPECT_EQ(accessorValues<float>(model, open.sparse.values.bufferView, 6),
            (std::vector<float>{0.0f, -1.25f, 0.5f, 0.0f, -0.75f, 0.0f}));
  const tinygltf::Accessor& still = model.accessors[static_cast<std::size_t>(primitive.targets[1].at("POSITION"))];
  EXPECT_FALSE(still.sparse.isSparse);
  EXPECT_EQ(still.bufferView, -1);

  ASSERT_EQ(model.animations.size(), 1u);
  const tinygltf::Animation& animation = model.animations[0];
  EXPECT_EQ(animation.channels.at(0).target_path, "weights");
  const tinygltf::AnimationSampler& sampler = animation.samplers.at(0);
  const tinygltf::Accessor& times = model.accessors[static_cast<std::size_t>(sampler.input)];
  const tinygltf::Accessor& values = model.accessors[static_cast<std::size_t>(sampler.output)];
  EXPECT_EQ(accessorValues<float>(model, times.bufferView, 4), (std::vector<float>{0.0f, 0.02f, 0.04f, 0.06f}));
  EXPECT_EQ(accessorValues<float>(model, values.bufferView, 8),
            (std::vector<float>{0.0f, 0.0f, 0.25f, 1.0f, 0.5f, 0.125f, 1.0f, 0.0f}));
}

TEST(GltfWriter, KeysOnlyTheFramesItIsGiven)
{
  const BlendshapeRig rig = twoShapeRig();
  Eigen::MatrixXd weights(5, 2);
  weights << 0.0, 0.0, 0.25, 0.5, 0.5, 1.0, 0.75, 1.0, 1.0, 1.0;
  const tinygltf::Model model = test::glbModel(rigGlb(rig, weights, 50.0, {0, 2, 4}));
  const tinygltf::AnimationSampler& sampler = model.animations.at(0).samplers.at(0);
  const tinygltf::Accessor& times = model.accessors[static_cast<std::size_t>(sampler.input)];
  const tinygltf::Accessor& values = model.accessors[static_cast<std::size_t>(sampler.output)];
  ASSERT_EQ(times.count, 3u);
  EXPECT_EQ(accessorValues<float>(model, times.bufferView, 3), (std::vector<float>{0.0f, 0.04f, 0.08f}));
  EXPECT_EQ(accessorValues<float>(model, values.bufferView, 6), (std::vector<float>{0.0f, 0.0f, 0.5f, 1.0f, 1.0f, 1.0f}));
  EXPECT_THROW((void)rigGlb(rig, weights, 50.0, {0, 2}), InvalidArgument) << "the last frame is a key";
  EXPECT_THROW((void)rigGlb(rig, weights, 50.0, {0, 3, 2, 4}), InvalidArgument) << "keys ascend";
}

TEST(GltfWriter, KeepsAStartTimeInTheAnimationsExtras)
{
  const BlendshapeRig rig = twoShapeRig();
  const Eigen::MatrixXd weights = Eigen::MatrixXd::Constant(3, 2, 0.5);
  const tinygltf::Model started = test::glbModel(rigGlb(rig, weights, 30.0, {}, 60951.2742));
  const tinygltf::Value& extras = started.animations.at(0).extras;
  ASSERT_TRUE(extras.Has("startSeconds"));
  EXPECT_DOUBLE_EQ(extras.Get("startSeconds").GetNumberAsDouble(), 60951.2742);
  const tinygltf::Accessor& times = started.accessors[static_cast<std::size_t>(started.animations[0].samplers.at(0).input)];
  EXPECT_EQ(accessorValues<float>(started, times.bufferView, 1).front(), 0.0f) << "the keys still start at 0";
  EXPECT_FALSE(test::glbModel(rigGlb(rig, weights, 30.0)).animations.at(0).extras.Has("startSeconds"));
  EXPECT_THROW((void)rigGlb(rig, weights, 30.0, {}, -1.0), InvalidArgument);
  EXPECT_THROW((void)rigGlb(rig, weights, 30.0, {}, std::nan("")), InvalidArgument);
}

TEST(GltfWriter, RefusesBadWeightsAndRates)
{
  const BlendshapeRig rig = twoShapeRig();
  EXPECT_THROW((void)rigGlb(rig, Eigen::MatrixXd::Zero(3, 1), 50.0), InvalidArgument);
  EXPECT_THROW((void)rigGlb(rig, Eigen::MatrixXd::Zero(3, 2), 0.0), InvalidArgument);
  Eigen::MatrixXd nan = Eigen::MatrixXd::Zero(3, 2);
  nan(1, 1) = std::nan("");
  EXPECT_THROW((void)rigGlb(rig, nan, 50.0), InvalidArgument);
  EXPECT_NO_THROW((void)test::glbModel(rigGlb(rig, Eigen::MatrixXd(0, 2), 50.0)));  // rig only, no animation
}

} // namespace
} // namespace mocap
