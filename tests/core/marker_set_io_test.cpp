#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/io/marker_set_io.h"
#include "mocap/io/take_io.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace mocap {
namespace {

MarkerSet sampleSet()
{
  return markerSetFromTake(readTake(test::sampleTake()));
}

TEST(MarkerSetIo, SetFromTheSampleTakeLeavesOutUnlabelledMarkersAndFindsPairsAndLinks)
{
  const MarkerSet set = sampleSet();
  EXPECT_EQ(set.size(), 37);  // 38 markers less the stray Unlabeled1
  EXPECT_EQ(std::count(set.labels.begin(), set.labels.end(), "Unlabeled1"), 0);
  EXPECT_TRUE(set.neutral.allFinite());
  EXPECT_FALSE(set.pairs.empty());
  EXPECT_GE(static_cast<Eigen::Index>(set.links.size()), set.size());
  EXPECT_NO_THROW(validateMarkerSet(set));
}

TEST(MarkerSetIo, RoundTripKeepsEverythingExactly)
{
  MarkerSet set = sampleSet();
  set.meshFile = "face.obj";
  set.meshVertices.assign(set.labels.size(), -1);
  set.meshVertices[2] = 812;
  test::TempDir dir;
  writeMarkerSet(set, dir.file("set.json"));
  const MarkerSet back = readMarkerSet(dir.file("set.json"));
  EXPECT_EQ(back.labels, set.labels);
  EXPECT_EQ(back.neutral, set.neutral);  // shortest round-trip numbers: bit for bit
  EXPECT_EQ(back.pairs, set.pairs);
  EXPECT_EQ(back.links, set.links);
  EXPECT_EQ(back.meshFile, "face.obj");
  EXPECT_EQ(back.meshVertices, set.meshVertices);
  EXPECT_EQ(back.units, set.units);
  EXPECT_EQ(back.symmetry().pairs().size(), set.pairs.size());
}

TEST(MarkerSetIo, PfaReadsPairsFromAMarkerSetFile)
{
  const MarkerSet set = sampleSet();
  test::TempDir dir;
  writeMarkerSet(set, dir.file("set.json"));
  std::vector<std::string> labels = set.labels;
  std::reverse(labels.begin(), labels.end());  // pairs go by label, not by index
  const MarkerSymmetry symmetry = readMarkerPairs(dir.file("set.json"), labels);
  ASSERT_EQ(symmetry.pairs().size(), set.pairs.size());
  for (const LabelPair& pair : set.pairs) {
    const auto at = [&](Eigen::Index i) {
      return static_cast<Eigen::Index>(std::find(labels.begin(), labels.end(), set.labels[static_cast<std::size_t>(i)]) -
                                       labels.begin());
    };
    EXPECT_EQ(symmetry.mirror(at(pair.first)), at(pair.second));
  }
  labels.pop_back();
  labels.erase(std::find(labels.begin(), labels.end(), set.labels[static_cast<std::size_t>(set.pairs[0].first)]));
  EXPECT_THROW((void)readMarkerPairs(dir.file("set.json"), labels), FormatError);
}

TEST(MarkerSetIo, MinimalFileAndOptionalMembers)
{
  const MarkerSet set = parseMarkerSet(
      R"({"format": "mocap-marker-set", "version": 1, "units": "cm",
          "markers": [{"label": "a", "position": [0, 0, 0]}, {"label": "b\u00e9", "position": [1, 2, 3.5e1]}],
          "pairs": [["a", "b\u00e9"]]})",
      "m.json");
  ASSERT_EQ(set.size(), 2);
  EXPECT_EQ(set.labels[1], "b\xc3\xa9");
  EXPECT_EQ(set.neutral(1, 2), 35.0);
  EXPECT_EQ(set.units, LengthUnit::Centimetre);
  EXPECT_TRUE(set.links.empty());
  EXPECT_TRUE(set.meshVertices.empty());
}

void expectFormatError(const std::string& text, const std::string& fragment)
{
  try {
    (void)parseMarkerSet(text, "m.json");
    FAIL() << "no error for " << text;
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("m.json"), std::string::npos) << e.what();
  }
}

TEST(MarkerSetIo, BadFilesGiveClearErrors)
{
  const std::string head = R"({"format": "mocap-marker-set", "version": 1, "markers": [)";
  const std::string two = R"({"label": "a", "position": [0, 0, 0]}, {"label": "b", "position": [1, 0, 0]}])";
  expectFormatError("{\"format\": ", "unexpected end");
  expectFormatError("[1, 2,]", "");
  expectFormatError(head + two + "} trailing", "unexpected text");
  expectFormatError(R"({"format": "other", "version": 1, "markers": []})", "format");
  expectFormatError(R"({"format": "mocap-marker-set", "version": 2, "markers": []})", "version");
  expectFormatError(head + two + R"(, "pairs": [["a", "c"]]})", "unknown label 'c'");
  expectFormatError(head + two + R"(, "pairs": [["a", "a"]]})", "itself");
  expectFormatError(head + R"({"label": "a", "position": [0, 0]}]})", "three numbers");
  expectFormatError(head + R"({"label": "a", "position": [0, 0, 0]}, {"label": "a", "position": [0, 0, 0]}]})",
                    "twice");
  expectFormatError(head + R"({"label": "a", "position": [0, 0, 0], "vertex": 1.5}]})", "integer");
  expectFormatError(head + R"({"label": "a", "position": [0, 0, "x"]}]})", "number");
  expectFormatError(std::string(300, '[') + std::string(300, ']'), "deeply");
  EXPECT_THROW((void)readMarkerSet("/nonexistent/set.json"), IoError);
}

TEST(MarkerSetIo, UnlabelledNamesFollowCaptureSoftwareConventions)
{
  for (const char* label : {"Unlabeled1", "unlabeled", "Unlabelled 3", "UNLABELED_12", "*17"})
    EXPECT_TRUE(isUnlabelledLabel(label)) << label;
  for (const char* label : {"Nose", "UnlabeledNose", "*", "*a1", "Lip_Unlabeled1", ""})
    EXPECT_FALSE(isUnlabelledLabel(label)) << label;
}

} // namespace
} // namespace mocap
