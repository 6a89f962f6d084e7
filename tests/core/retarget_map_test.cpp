#include "mocap/io/retarget_map_io.h"
#include "mocap/model/retarget_map.h"

#include "checkout_paths.h"
#include "error_text.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>

namespace mocap {
namespace {

using test::errorOf;

std::filesystem::path shippedMap(const std::string& name)
{
  return std::filesystem::path(checkout::sourceDir()) / "resources" / "retarget" / name;
}

/// The 52 ARKit names of a real Live Link Face recording's header, in the app's order.
std::vector<std::string> liveLinkFaceWeightNames()
{
  std::ifstream in(test::dataFile("livelink_face/alex_rom_4_first200.csv"));
  std::string header;
  std::getline(in, header);
  std::vector<std::string> names;
  std::size_t start = 0;
  for (std::size_t comma = header.find(','); start <= header.size(); comma = header.find(',', start)) {
    names.push_back(header.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos)
      break;
    start = comma + 1;
  }
  return {names.begin() + 2, names.begin() + 54};  // after Timecode and BlendShapeCount
}

TEST(RetargetMap, MixesSourcesWithGainsOffsetAndClamp)
{
  RetargetMap map;
  map.channels.push_back({"Smile", {{"smile_L", 0.5}, {"smile_R", 0.5}}, 0.0, 0.0, 1.0, 0});
  map.channels.push_back({"JawBig", {{"jaw", 2.0}}, 0.1, 0.0, 1.0, 0});
  map.channels.push_back({"Constant", {}, 0.25});
  Eigen::MatrixXd weights(3, 3);  // jaw, smile_L, smile_R
  weights << 0.0, 0.0, 0.0,  //
      0.2, 1.0, 0.0,         //
      0.9, 1.0, 1.0;
  const MappedWeights mapped = applyRetargetMap(map, {"jaw", "smile_L", "smile_R"}, weights);
  EXPECT_EQ(mapped.names, (std::vector<std::string>{"Smile", "JawBig", "Constant"}));
  Eigen::MatrixXd expected(3, 3);
  expected << 0.0, 0.1, 0.25,  //
      0.5, 0.5, 0.25,          //
      1.0, 1.0, 0.25;          // 0.1 + 1.8 clamped to 1
  EXPECT_TRUE(mapped.weights.isApprox(expected, 1e-12)) << mapped.weights;
}

TEST(RetargetMap, RoundTripsThroughItsJson)
{
  RetargetMap map;
  map.channels.push_back({"A", {{"x", 0.5}, {"y", -1.5}}, 0.125, 0.0, 1.0, 0});
  map.channels.push_back({"B", {{"z", 1.0}}});
  const RetargetMap back = parseRetargetMap(retargetMapJson(map), "map.json");
  ASSERT_EQ(back.channels.size(), 2u);
  EXPECT_EQ(back.channels[0].name, "A");
  EXPECT_EQ(back.channels[0].sources.size(), 2u);
  EXPECT_EQ(back.channels[0].sources[1].shape, "y");
  EXPECT_EQ(back.channels[0].sources[1].gain, -1.5);
  EXPECT_EQ(back.channels[0].offset, 0.125);
  EXPECT_EQ(back.channels[0].max, 1.0);
  EXPECT_TRUE(std::isinf(back.channels[1].min) && back.channels[1].min < 0.0) << "no clamp stays no clamp";
  EXPECT_EQ(retargetMapJson(back), retargetMapJson(map));
}

TEST(RetargetMap, ErrorsNameTheLineOfTheChannel)
{
  const std::string text = "{\n"
                           "  \"format\": \"mocap retarget map\",\n"
                           "  \"version\": 1,\n"
                           "  \"channels\": [\n"
                           "    {\"name\": \"JawOpen\", \"sources\": [{\"shape\": \"jawOpen\"}]},\n"
                           "    {\"name\": \"Smile\",\n"
                           "     \"sources\": [{\"shape\": \"mouthSmile\", \"gain\": 2}], \"min\": 1, \"max\": 0}\n"
                           "  ]\n"
                           "}\n";
  EXPECT_NE(errorOf([&] { (void)parseRetargetMap(text, "m.json"); }).find("channel 'Smile' (line 6)"), std::string::npos)
      << errorOf([&] { (void)parseRetargetMap(text, "m.json"); });
  std::string unknownShape = text;
  unknownShape.replace(unknownShape.find("\"min\": 1, \"max\": 0"), 18, "\"min\": 0, \"max\": 1");
  const RetargetMap map = parseRetargetMap(unknownShape, "m.json");
  const std::string lacks = errorOf([&] { (void)applyRetargetMap(map, {"jawOpen"}, Eigen::MatrixXd::Zero(2, 1)); });
  EXPECT_NE(lacks.find("channel 'Smile' (line 6) takes 'mouthSmile', a shape the rig does not have"), std::string::npos)
      << lacks;
  std::string misspelt = unknownShape;
  misspelt.replace(misspelt.find("\"gain\""), 6, "\"gian\"");
  const std::string key = errorOf([&] { (void)parseRetargetMap(misspelt, "m.json"); });
  EXPECT_NE(key.find("line 6"), std::string::npos) << key;
  EXPECT_NE(key.find("\"gian\""), std::string::npos) << key;
  EXPECT_NE(errorOf([&] { (void)parseRetargetMap("{\"format\": \"mocap retarget map\", \"version\": 2, \"channels\": []}", "m"); })
                .find("version 1"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { (void)parseRetargetMap("{\"format\": \"other\"}", "m"); }).find("not a retarget map"),
            std::string::npos);
  EXPECT_FALSE(errorOf([&] { (void)parseRetargetMap("{\"format\": NaN}", "m"); }).empty());
  RetargetMap twice = identityRetargetMap({"a", "a"});
  EXPECT_NE(errorOf([&] { checkRetargetMap(twice); }).find("named twice"), std::string::npos);
}

TEST(RetargetMap, TheShippedIctToArkitMapGivesLiveLinkFacesNamesInItsOrder)
{
  const RetargetMap arkit = readRetargetMap(shippedMap("ict_to_arkit.json"));
  std::vector<std::string> names;
  for (const RetargetChannel& channel : arkit.channels)
    names.push_back(channel.name);
  EXPECT_EQ(names, liveLinkFaceWeightNames());
  // Every source is a shape of the bundled ICT rig (the identity template lists them all), and
  // every rig shape is used: the shapes ICT splits in two (browInnerUp, cheekPuff) are averaged.
  const RetargetMap identity = readRetargetMap(shippedMap("ict_identity.json"));
  std::vector<std::string> ict;
  for (const RetargetChannel& channel : identity.channels)
    ict.push_back(channel.name);
  EXPECT_EQ(ict.size(), 53u);
  EXPECT_EQ(retargetMapJson(identity), retargetMapJson(identityRetargetMap(ict)));
  std::set<std::string> used;
  for (const RetargetChannel& channel : arkit.channels)
    for (const RetargetSource& source : channel.sources)
      used.insert(source.shape);
  EXPECT_EQ(used, std::set<std::string>(ict.begin(), ict.end()));
  Eigen::MatrixXd oneSide = Eigen::MatrixXd::Zero(1, 53);
  const auto innerLeft = std::find(ict.begin(), ict.end(), "browInnerUp_L") - ict.begin();
  oneSide(0, innerLeft) = 1.0;
  const MappedWeights mapped = applyRetargetMap(arkit, ict, oneSide);
  const auto browInnerUp = std::find(names.begin(), names.end(), "BrowInnerUp") - names.begin();
  EXPECT_DOUBLE_EQ(mapped.weights(0, browInnerUp), 0.5);
  EXPECT_DOUBLE_EQ(mapped.weights.sum(), 0.5);
}

} // namespace
} // namespace mocap
