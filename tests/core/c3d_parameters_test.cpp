#include "mocap/model/c3d_parameters.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mocap {
namespace {

TEST(C3dParameters, CharArraysSplitIntoTrimmedStrings)
{
  const C3dParameter p = C3dParameter::makeStrings("LABELS", {"HEAD", "L Toe", "x"});
  EXPECT_EQ(p.dimensions, (std::vector<int>{5, 3}));
  EXPECT_EQ(p.strings(), (std::vector<std::string>{"HEAD", "L Toe", "x"}));
  C3dParameter units;
  units.type = C3dType::Char;
  units.dimensions = {4};
  units.chars = "mm  ";
  EXPECT_EQ(units.strings(), std::vector<std::string>{"mm"});
}

TEST(C3dParameters, Int16CountsAboveSignedRangeReadUnsigned)
{
  const C3dParameter frames = C3dParameter::makeInt16("FRAMES", {40000}, true);
  EXPECT_LT(*frames.number(), 0.0);
  EXPECT_EQ(*frames.unsignedInt16(), 40000);
  EXPECT_TRUE(frames.dimensions.empty());
}

TEST(C3dParameters, AFloatCountOutsideTheUnsigned16BitRangeIsNone)
{
  // Found by fuzz_c3d_reader: 6.29e8 in a float parameter read as a count was undefined behaviour.
  EXPECT_FALSE(C3dParameter::makeFloat("USED", {6.29148e8}, true).unsignedInt16().has_value());
  EXPECT_FALSE(C3dParameter::makeFloat("USED", {-3.0}, true).unsignedInt16().has_value());
  EXPECT_FALSE(C3dParameter::makeFloat("USED", {std::nan("")}, true).unsignedInt16().has_value());
  EXPECT_EQ(*C3dParameter::makeFloat("USED", {65535.0}, true).unsignedInt16(), 65535);
}

TEST(C3dParameters, TreeLookupIsCaseInsensitiveAndSetKeepsDescriptions)
{
  C3dParameterTree tree;
  C3dParameter rate = C3dParameter::makeFloat("RATE", {50.0}, true);
  rate.description = "video rate";
  tree.set("point", rate);
  EXPECT_EQ(tree.groups().size(), 1u);
  EXPECT_EQ(tree.groups()[0].name, "POINT");
  tree.set("POINT", C3dParameter::makeFloat("rate", {100.0}, true));
  EXPECT_EQ(*tree.number("Point", "Rate"), 100.0);
  EXPECT_EQ(tree.find("POINT", "RATE")->description, "video rate");
  EXPECT_EQ(tree.ensureGroup("ANALOG").id, 2);
  tree.remove("POINT", "RATE");
  EXPECT_EQ(tree.find("POINT", "RATE"), nullptr);
  EXPECT_FALSE(tree.number("NOPE", "RATE").has_value());
}

} // namespace
} // namespace mocap
