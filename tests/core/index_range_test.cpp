// parseIndexRange: the one reader of FIRST:LAST ranges (`--frames`, `--vertices`).
#include "mocap/base/error.h"
#include "mocap/base/index_range.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace mocap {
namespace {

constexpr std::int64_t kLowest = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kHighest = std::numeric_limits<std::int64_t>::max();

/// The message parseIndexRange(text, lowest, highest) throws, or "" when it reads the range.
std::string errorOf(const std::string& text, std::int64_t lowest = 0, std::int64_t highest = 100)
{
  try {
    (void)parseIndexRange(text, lowest, highest);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

void expectRange(const std::string& text, std::int64_t first, std::int64_t last, std::int64_t lowest = 0)
{
  const IndexRange range = parseIndexRange(text, lowest, 100);
  EXPECT_EQ(range.first, first) << text;
  EXPECT_EQ(range.last, last) << text;
}

TEST(IndexRange, ReadsTheFormsTheRangeOptionsAlwaysTook)
{
  expectRange("10:20", 10, 20);
  expectRange("7:7", 7, 7);
  expectRange("0:100", 0, 100);
  expectRange("010:020", 10, 20);  // decimal, not octal
  expectRange("+3:+4", 3, 4);
  expectRange(" 3 : 4 ", 3, 4);
  expectRange("-5:-2", -5, -2, -10);  // frame numbers may be negative where the take's are
  const IndexRange wide = parseIndexRange("-9223372036854775808:9223372036854775807", kLowest, kHighest);
  EXPECT_EQ(wide.first, kLowest);
  EXPECT_EQ(wide.last, kHighest);
}

TEST(IndexRange, RefusesTrailingAndOtherTextNamingTheBadPart)
{
  EXPECT_EQ(errorOf("10:20x"), "LAST '20x' is not a whole number");
  EXPECT_EQ(errorOf("10x:20"), "FIRST '10x' is not a whole number");
  EXPECT_EQ(errorOf("10:20 30"), "LAST '20 30' is not a whole number");
  EXPECT_EQ(errorOf("1:2:3"), "LAST '2:3' is not a whole number");
  EXPECT_EQ(errorOf("1.5:3"), "FIRST '1.5' is not a whole number");
  EXPECT_EQ(errorOf("0x10:20"), "FIRST '0x10' is not a whole number");
  EXPECT_EQ(errorOf("+-3:4"), "FIRST '+-3' is not a whole number");
  EXPECT_EQ(errorOf("+:4"), "FIRST '+' is not a whole number");
  EXPECT_EQ(errorOf("7-9"), "no ':' between FIRST and LAST");
  EXPECT_EQ(errorOf(""), "no ':' between FIRST and LAST");
  EXPECT_EQ(errorOf(":20"), "FIRST is empty");
  EXPECT_EQ(errorOf("10:"), "LAST is empty");
  EXPECT_EQ(errorOf(" : "), "FIRST is empty");
}

TEST(IndexRange, RefusesReversedNegativeOutOfBoundsAndOverflowingRanges)
{
  EXPECT_EQ(errorOf("5:2"), "LAST 2 is before FIRST 5");
  EXPECT_EQ(errorOf("-3:5"), "FIRST -3 is less than 0");
  EXPECT_EQ(errorOf("0:101"), "LAST 101 is more than 100");
  EXPECT_EQ(errorOf("1:3", 2, 10), "FIRST 1 is less than 2");
  EXPECT_EQ(errorOf("0:0", 0, -1), "LAST 0 is more than -1");  // nothing to choose from
  EXPECT_EQ(errorOf("0:9223372036854775808", kLowest, kHighest),
            "LAST '9223372036854775808' does not fit a 64-bit whole number");
  EXPECT_EQ(errorOf("-99999999999999999999:0", kLowest, kHighest),
            "FIRST '-99999999999999999999' does not fit a 64-bit whole number");
}

} // namespace
} // namespace mocap
