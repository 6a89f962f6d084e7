#include "mocap/io/bvh_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

using mocap::test::TempDir;

// What a whitespace-splitting BVH reader sees in the text.
struct ParsedBvh
{
  std::string root;
  std::vector<std::string> joints;
  std::vector<Eigen::Vector3d> jointOffsets;
  std::vector<int> channelCounts;
  int endSites = 0;
  int depth = 0;  // brace balance at MOTION
  long frames = -1;
  double frameTime = 0.0;
  std::vector<std::vector<double>> motion;
};

// O(text size).
ParsedBvh parseBvh(const std::string& text)
{
  ParsedBvh bvh;
  std::istringstream lines(text);
  std::string line;
  bool inMotion = false;
  bool jointPending = false;
  while (std::getline(lines, line)) {
    std::istringstream in(line);
    std::vector<std::string> tokens;
    for (std::string token; in >> token;)
      tokens.push_back(token);
    if (tokens.empty())
      continue;
    if (inMotion) {
      if (tokens[0] == "Frames:") {
        bvh.frames = std::stol(tokens.at(1));
      } else if (tokens[0] == "Frame" && tokens.size() == 3) {
        bvh.frameTime = std::strtod(tokens[2].c_str(), nullptr);
      } else {
        std::vector<double> values;
        for (const std::string& token : tokens) {
          char* end = nullptr;
          values.push_back(std::strtod(token.c_str(), &end));
          EXPECT_EQ(*end, '\0') << "not a number: " << token;
        }
        bvh.motion.push_back(values);
      }
    } else if (tokens[0] == "ROOT") {
      bvh.root = tokens.at(1);
    } else if (tokens[0] == "JOINT") {
      EXPECT_EQ(tokens.size(), 2U) << line;
      bvh.joints.push_back(tokens.at(1));
      jointPending = true;
    } else if (tokens[0] == "OFFSET" && jointPending) {
      bvh.jointOffsets.emplace_back(std::stod(tokens.at(1)), std::stod(tokens.at(2)),
                                    std::stod(tokens.at(3)));
      jointPending = false;
    } else if (tokens[0] == "CHANNELS") {
      bvh.channelCounts.push_back(std::stoi(tokens.at(1)));
      EXPECT_EQ(tokens.size(), static_cast<std::size_t>(bvh.channelCounts.back() + 2)) << line;
    } else if (tokens[0] == "End") {
      ++bvh.endSites;
    } else if (tokens[0] == "{") {
      ++bvh.depth;
    } else if (tokens[0] == "}") {
      --bvh.depth;
    } else if (tokens[0] == "MOTION") {
      inMotion = true;
    }
  }
  return bvh;
}

// Rz·Rx·Ry built independently of the code under test. O(1).
Eigen::Matrix3d rotationZxy(double zDegrees, double xDegrees, double yDegrees)
{
  const double k = kPi / 180.0;
  return (Eigen::AngleAxisd(zDegrees * k, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(xDegrees * k, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(yDegrees * k, Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
}

// Six frames of three markers, one of them labelled like the root; Chin misses frame 0. O(1).
mocap::Take movingTake()
{
  mocap::Take take({"Nose Tip", "Chin", "Head"}, 6, 100.0);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      const double t = static_cast<double>(f);
      take.setPosition(f, m, Eigen::Vector3d(10.0 * static_cast<double>(m) + t, 100.0 - 0.5 * t, 3.25 * t));
      take.valid()(f, m) = true;
    }
  }
  take.valid()(0, 1) = false;  // Chin's first valid sample is frame 1
  return take;
}

} // namespace

TEST(BvhWriter, StructureMatchesTake)
{
  const mocap::Take take = movingTake();
  const std::string text = mocap::formatBvh(take);
  EXPECT_EQ(text.rfind("HIERARCHY\nROOT Head\n{\n  OFFSET 0 0 0\n"
                       "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n",
                       0),
            0U);
  const ParsedBvh bvh = parseBvh(text);
  EXPECT_EQ(bvh.root, "Head");
  EXPECT_EQ(bvh.joints, (std::vector<std::string>{"Nose_Tip", "Chin", "Head_2"}));
  EXPECT_EQ(bvh.channelCounts, (std::vector<int>{6, 3, 3, 3}));
  EXPECT_EQ(bvh.endSites, 3);
  EXPECT_EQ(bvh.depth, 0);
  EXPECT_EQ(bvh.frames, 6);
  EXPECT_NE(text.find("\nFrame Time: 0.01\n"), std::string::npos);
  EXPECT_EQ(bvh.frameTime, 0.01);
  ASSERT_EQ(bvh.motion.size(), 6U);
  for (const std::vector<double>& values : bvh.motion)
    EXPECT_EQ(values.size(), 6U + 3U * 3U);
}

TEST(BvhWriter, IdentityHeadWritesTakePositions)
{
  const mocap::Take take = movingTake();
  const ParsedBvh bvh = parseBvh(mocap::formatBvh(take));
  ASSERT_EQ(bvh.motion.size(), 6U);
  EXPECT_EQ(bvh.jointOffsets.at(0), take.position(0, 0));
  EXPECT_EQ(bvh.jointOffsets.at(1), take.position(1, 1));  // first valid sample of Chin
  for (Eigen::Index f = 1; f < take.frameCount(); ++f) {
    const std::vector<double>& values = bvh.motion[static_cast<std::size_t>(f)];
    for (std::size_t i = 0; i < 6; ++i)
      EXPECT_EQ(values[i], 0.0);
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      const auto at = static_cast<std::size_t>(6 + 3 * m);
      EXPECT_EQ(Eigen::Vector3d(values[at], values[at + 1], values[at + 2]), take.position(f, m));
    }
  }
}

TEST(BvhWriter, HeadPoseIsFactoredOut)
{
  const mocap::Take take = movingTake();
  mocap::BvhOptions options;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> angle(-170.0, 170.0);
  std::uniform_real_distribution<double> shift(-500.0, 500.0);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = rotationZxy(angle(random), angle(random) / 2.0, angle(random));
    pose.translation() = Eigen::Vector3d(shift(random), shift(random), shift(random));
    options.headPoses.push_back(pose);
  }
  const ParsedBvh bvh = parseBvh(mocap::formatBvh(take, options));
  ASSERT_EQ(bvh.motion.size(), 6U);

  const Eigen::Vector3d chinRest = options.headPoses[1].inverse() * take.position(1, 1);
  EXPECT_LT((bvh.jointOffsets.at(1) - chinRest).norm(), 1e-9);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    const std::vector<double>& v = bvh.motion[static_cast<std::size_t>(f)];
    const Eigen::Vector3d translation(v[0], v[1], v[2]);
    const Eigen::Matrix3d rotation = rotationZxy(v[3], v[4], v[5]);
    const Eigen::Isometry3d& pose = options.headPoses[static_cast<std::size_t>(f)];
    EXPECT_LT((translation - pose.translation()).norm(), 1e-12);
    EXPECT_LT((rotation - pose.linear()).norm(), 1e-9) << "frame " << f;
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      if (!take.isValid(f, m))
        continue;
      const auto at = static_cast<std::size_t>(6 + 3 * m);
      const Eigen::Vector3d world = translation + rotation * Eigen::Vector3d(v[at], v[at + 1], v[at + 2]);
      EXPECT_LT((world - take.position(f, m)).norm(), 1e-9) << "frame " << f << " marker " << m;
    }
  }
  // Chin's gap at frame 0 holds its head-space position of frame 1.
  EXPECT_EQ(bvh.motion[0][9], bvh.motion[1][9]);
  EXPECT_EQ(bvh.motion[0][11], bvh.motion[1][11]);
}

TEST(BvhWriter, GapsRepeatNearestValidSample)
{
  mocap::Take take({"Gappy", "Never"}, 8, 50.0);
  for (Eigen::Index f : {1, 5}) {
    take.setPosition(f, 0, Eigen::Vector3d(static_cast<double>(f), 2.0 * static_cast<double>(f), -7.5));
    take.valid()(f, 0) = true;
  }
  // A non-finite position flagged valid must not leak into the file.
  take.setPosition(6, 0, Eigen::Vector3d(std::nan(""), 0.0, 0.0));
  take.valid()(6, 0) = true;
  take.setPosition(2, 1, Eigen::Vector3d(9.0, 9.0, 9.0));  // invalid: must not be written

  const std::string text = mocap::formatBvh(take);
  EXPECT_EQ(text.find('#'), std::string::npos);
  EXPECT_EQ(text.find("nan"), std::string::npos);
  const ParsedBvh bvh = parseBvh(text);
  ASSERT_EQ(bvh.motion.size(), 8U);
  EXPECT_EQ(bvh.frameTime, 0.02);
  EXPECT_EQ(bvh.jointOffsets.at(0), Eigen::Vector3d(1.0, 2.0, -7.5));
  EXPECT_EQ(bvh.jointOffsets.at(1), Eigen::Vector3d::Zero());
  // Nearest valid frame per frame; frame 3 is as far from 1 as from 5 and takes the earlier one.
  const int source[] = {1, 1, 1, 1, 5, 5, 5, 5};
  for (std::size_t f = 0; f < 8; ++f) {
    const std::vector<double>& v = bvh.motion[f];
    ASSERT_EQ(v.size(), 12U);
    EXPECT_EQ(v[6], static_cast<double>(source[f])) << "frame " << f;
    EXPECT_EQ(v[7], 2.0 * static_cast<double>(source[f])) << "frame " << f;
    EXPECT_EQ(v[8], -7.5);
    EXPECT_EQ(v[9], 0.0);
    EXPECT_EQ(v[10], 0.0);
    EXPECT_EQ(v[11], 0.0);
  }
}

TEST(BvhWriter, RejectsWrongHeadPoseCount)
{
  const mocap::Take take = movingTake();
  mocap::BvhOptions options;
  options.headPoses.assign(5, Eigen::Isometry3d::Identity());
  EXPECT_THROW((void)mocap::formatBvh(take, options), mocap::InvalidArgument);
  options.headPoses.assign(6, Eigen::Isometry3d::Identity());
  EXPECT_NO_THROW((void)mocap::formatBvh(take, options));
}

TEST(BvhWriter, ZxyEulerRoundTrip)
{
  // Known angles come back, and the matrix is Rz·Rx·Ry.
  const Eigen::Vector3d zxy(30.0, -20.0, 45.0);
  EXPECT_LT((mocap::zxyEulerDegrees(rotationZxy(30.0, -20.0, 45.0)) - zxy).norm(), 1e-12);
  EXPECT_LT((mocap::zxyRotation(zxy) - rotationZxy(30.0, -20.0, 45.0)).norm(), 1e-15);
  EXPECT_EQ(mocap::zxyEulerDegrees(Eigen::Matrix3d::Identity()), Eigen::Vector3d::Zero());

  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Quaterniond q(normal(random), normal(random), normal(random), normal(random));
    const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
    const Eigen::Vector3d angles = mocap::zxyEulerDegrees(r);
    EXPECT_LE(std::abs(angles[1]), 90.0);
    EXPECT_LT((rotationZxy(angles[0], angles[1], angles[2]) - r).norm(), 1e-12) << "trial " << i;
  }
  // Gimbal lock and its neighbourhood.
  for (double x : {90.0, -90.0, 89.9999999, -89.99999999}) {
    for (double z : {0.0, 37.0, -150.0}) {
      const Eigen::Matrix3d r = rotationZxy(z, x, 25.0);
      const Eigen::Vector3d angles = mocap::zxyEulerDegrees(r);
      EXPECT_LT((rotationZxy(angles[0], angles[1], angles[2]) - r).norm(), 1e-9) << x << " " << z;
    }
  }
}

TEST(BvhWriter, WritesFile)
{
  const TempDir dir;
  const mocap::Take take = movingTake();
  const fs::path file = dir.path() / "take.bvh";
  mocap::writeBvh(take, file);
  EXPECT_EQ(mocap::readFileBytes(file), mocap::formatBvh(take));

  const mocap::Take empty({}, 0, 30.0);
  const ParsedBvh bvh = parseBvh(mocap::formatBvh(empty));
  EXPECT_EQ(bvh.frames, 0);
  EXPECT_EQ(bvh.endSites, 1);
  EXPECT_EQ(bvh.depth, 0);
  EXPECT_TRUE(bvh.motion.empty());
}
