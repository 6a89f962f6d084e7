// The sidecar beside a take that remembers its reference videos (TAKE.c3d.video.json): written
// and read back, found again after the folder moves, a missing video kept as it was stored, and
// malformed sidecars refused with the file named.
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/video/reference_video_sidecar.h"

#include <gtest/gtest.h>

#include <fstream>

namespace mocap {
namespace {

void touch(const std::filesystem::path& path)
{
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << "video bytes\n";
}

void writeText(const std::filesystem::path& path, const std::string& text)
{
  std::ofstream(path) << text;
}

TEST(ReferenceVideoSidecar, IsNamedAfterTheTakesFullFileName)
{
  EXPECT_EQ(referenceVideoSidecarPath("shoot/take 1.c3d"), std::filesystem::path("shoot/take 1.c3d.video.json"));
  EXPECT_NE(referenceVideoSidecarPath("a.c3d"), referenceVideoSidecarPath("a.trc"));
}

TEST(ReferenceVideoSidecar, WritesAndReadsBackPathsAndOffsets)
{
  test::TempDir dir, elsewhere;
  const auto take = dir.file("take.c3d");
  const auto beside = dir.file("video/witness cam.mp4");
  const auto far = elsewhere.file("hmc.mov");
  touch(beside);
  touch(far);
  writeReferenceVideoSidecar(take, {linkReferenceVideo(beside, take, 0.52), linkReferenceVideo(far, take, -1.25)});
  const std::string text = readFileBytes(referenceVideoSidecarPath(take));
  EXPECT_NE(text.find("\"video/witness cam.mp4\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"format\": \"mocap reference videos\""), std::string::npos) << text;
  const auto links = readReferenceVideoSidecar(take);
  ASSERT_EQ(links.size(), 2u);
  EXPECT_EQ(links[0].path, beside.lexically_normal());
  EXPECT_EQ(links[0].relative, std::filesystem::path("video/witness cam.mp4"));
  EXPECT_DOUBLE_EQ(links[0].offset, 0.52);
  EXPECT_TRUE(links[0].found);
  EXPECT_EQ(links[1].path, far.lexically_normal());
  EXPECT_DOUBLE_EQ(links[1].offset, -1.25);
  EXPECT_TRUE(links[1].found);
  // No links: the sidecar goes, and a take without one has no videos.
  writeReferenceVideoSidecar(take, {});
  EXPECT_FALSE(std::filesystem::exists(referenceVideoSidecarPath(take)));
  EXPECT_TRUE(readReferenceVideoSidecar(take).empty());
}

TEST(ReferenceVideoSidecar, AFolderMovedWithItsVideosFindsThemByTheRelativePath)
{
  test::TempDir dir;
  const auto shoot = dir.path() / "shoot";
  touch(shoot / "take.c3d");
  touch(shoot / "video/cam.mp4");
  writeReferenceVideoSidecar(shoot / "take.c3d", {linkReferenceVideo(shoot / "video/cam.mp4", shoot / "take.c3d", 2.0)});
  const auto moved = dir.path() / "archive";
  std::filesystem::rename(shoot, moved);
  const auto links = readReferenceVideoSidecar(moved / "take.c3d");
  ASSERT_EQ(links.size(), 1u);
  EXPECT_TRUE(links[0].found);
  EXPECT_EQ(links[0].path, (moved / "video/cam.mp4").lexically_normal());
  EXPECT_DOUBLE_EQ(links[0].offset, 2.0);
}

TEST(ReferenceVideoSidecar, AMissingVideoComesBackAsStoredAndWritingItBackLosesNothing)
{
  test::TempDir dir, elsewhere;
  const auto take = dir.file("take.c3d");
  const auto gone = elsewhere.file("gone.mp4");
  const auto kept = dir.file("kept.mp4");
  touch(gone);
  touch(kept);
  writeReferenceVideoSidecar(take, {linkReferenceVideo(gone, take, 0.25), linkReferenceVideo(kept, take, 0.0)});
  const std::string before = readFileBytes(referenceVideoSidecarPath(take));
  std::filesystem::remove(gone);
  const auto links = readReferenceVideoSidecar(take);
  ASSERT_EQ(links.size(), 2u);
  EXPECT_FALSE(links[0].found);
  EXPECT_EQ(links[0].path, gone.lexically_normal());
  EXPECT_FALSE(links[0].relative.empty());
  EXPECT_DOUBLE_EQ(links[0].offset, 0.25);
  EXPECT_TRUE(links[1].found);
  writeReferenceVideoSidecar(take, links);
  EXPECT_EQ(readFileBytes(referenceVideoSidecarPath(take)), before);
}

TEST(ReferenceVideoSidecar, MalformedSidecarsAreRefusedNamingTheFile)
{
  test::TempDir dir;
  const auto take = dir.file("take.c3d");
  const auto sidecar = referenceVideoSidecarPath(take);
  const std::vector<std::string> bad = {
      "{ not json",
      "[]",
      R"({"format": "something else", "version": 1, "videos": []})",
      R"({"format": "mocap reference videos", "version": 2, "videos": []})",
      R"({"format": "mocap reference videos", "version": 1})",
      R"({"format": "mocap reference videos", "version": 1, "videos": [{"offset": 1}]})",
      R"({"format": "mocap reference videos", "version": 1, "videos": [{"path": "a.mp4", "offset": "soon"}]})",
      R"({"format": "mocap reference videos", "version": 1, "videos": [{"path": 3}]})",
  };
  for (const std::string& text : bad) {
    writeText(sidecar, text);
    try {
      (void)readReferenceVideoSidecar(take);
      ADD_FAILURE() << "accepted " << text;
    } catch (const FormatError& e) {
      EXPECT_NE(std::string(e.what()).find("take.c3d.video.json"), std::string::npos) << e.what();
    }
  }
  // A valid one with an absolute path only reads.
  writeText(sidecar, R"({"format": "mocap reference videos", "version": 1, "videos": [{"absolute_path": "/nowhere/a.mp4"}]})");
  const auto links = readReferenceVideoSidecar(take);
  ASSERT_EQ(links.size(), 1u);
  EXPECT_FALSE(links[0].found);
  EXPECT_EQ(links[0].path, std::filesystem::path("/nowhere/a.mp4"));
  EXPECT_DOUBLE_EQ(links[0].offset, 0.0);
}

} // namespace
} // namespace mocap
