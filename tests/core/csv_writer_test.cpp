#include "mocap/io/csv_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "test_support.h"
#include "mocap/base/text.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>
#include <string>

namespace {

namespace fs = std::filesystem;

using mocap::test::TempDir;

// Three frames of three awkwardly named markers with two gaps. O(1).
mocap::Take csvTake()
{
  mocap::Take take({"A", "B,1", "say \"hi\""}, 3, 100.0);
  take.setFirstFrame(10);
  for (Eigen::Index f = 0; f < 3; ++f) {
    for (Eigen::Index m = 0; m < 3; ++m) {
      take.setPosition(f, m, Eigen::Vector3d(static_cast<double>(f), 0.5 * static_cast<double>(m), -1.25));
      take.valid()(f, m) = true;
    }
  }
  take.valid()(1, 1) = false;
  take.valid()(2, 0) = false;
  return take;
}

} // namespace

TEST(CsvWriter, HeaderQuotesLabelsPerRfc4180)
{
  const std::string text = mocap::formatCsv(csvTake());
  const std::string header = text.substr(0, text.find('\n'));
  EXPECT_EQ(header, "Frame,Time,A:X,A:Y,A:Z,\"B,1:X\",\"B,1:Y\",\"B,1:Z\","
                    "\"say \"\"hi\"\":X\",\"say \"\"hi\"\":Y\",\"say \"\"hi\"\":Z\"");
}

TEST(CsvWriter, RowsHaveFrameTimeAndEmptyCellsForGaps)
{
  const std::string text = mocap::formatCsv(csvTake());
  const std::vector<std::string_view> lines = mocap::split(text, '\n');
  ASSERT_EQ(lines.size(), 5U);  // header, 3 rows, empty after the final line break
  EXPECT_EQ(lines[1], "10,0,0,0,-1.25,0,0.5,-1.25,0,1,-1.25");
  EXPECT_EQ(lines[2], "11,0.01,1,0,-1.25,,,,1,1,-1.25");
  EXPECT_EQ(lines[3], "12,0.02,,,,2,0.5,-1.25,2,1,-1.25");
  EXPECT_TRUE(lines[4].empty());
}

TEST(CsvWriter, NumbersReadBackExactly)
{
  mocap::Take take({"M"}, 50, 240.0);
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> value(-1e6, 1e6);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    const double asFloat = static_cast<double>(static_cast<float>(value(random)));
    take.setPosition(f, 0, Eigen::Vector3d(value(random), asFloat, 1e-9 * value(random)));
    take.valid()(f, 0) = true;
  }
  const std::string text = mocap::formatCsv(take);
  const std::vector<std::string_view> lines = mocap::split(text, '\n');
  ASSERT_EQ(lines.size(), 52U);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    const std::vector<std::string_view> cells = mocap::split(lines[static_cast<std::size_t>(f + 1)], ',');
    ASSERT_EQ(cells.size(), 5U);
    EXPECT_EQ(std::strtod(std::string(cells[1]).c_str(), nullptr), take.timeOf(f));
    for (Eigen::Index axis = 0; axis < 3; ++axis)
      EXPECT_EQ(std::strtod(std::string(cells[static_cast<std::size_t>(2 + axis)]).c_str(), nullptr),
                take.position(f, 0)[axis]);
  }
}

TEST(CsvWriter, WritesFileAndRejectsOverflowingFrameNumbers)
{
  const TempDir dir;
  mocap::Take take = csvTake();
  const fs::path file = dir.path() / "take.csv";
  mocap::writeCsv(take, file);
  EXPECT_EQ(mocap::readFileBytes(file), mocap::formatCsv(take));

  take.setFirstFrame(std::numeric_limits<std::int64_t>::max() - 1);
  EXPECT_THROW((void)mocap::formatCsv(take), mocap::InvalidArgument);
}
