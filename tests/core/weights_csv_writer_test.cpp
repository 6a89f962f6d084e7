// Blendshape-weight CSV: the plain Frame,Time layout and Live Link Face's Timecode layout.
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/weights_csv_writer.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

TEST(WeightsCsvWriter, PlainLayoutNumbersFramesAsTheTakeAndTimesInSeconds)
{
  Eigen::MatrixXd w(3, 2);
  w << 0.0, 1.0, 0.25, 0.5, 0.125, 0.0;
  EXPECT_EQ(weightsCsvText({"jawOpen", "mouth,odd"}, w, 10, 4.0, WeightsCsvLayout::Plain),
            "Frame,Time,jawOpen,\"mouth,odd\"\n10,0,0,1\n11,0.25,0.25,0.5\n12,0.5,0.125,0\n");
}

TEST(WeightsCsvWriter, LiveLinkTimecodeCountsFramesWithinTheSecond)
{
  const Eigen::MatrixXd w = Eigen::MatrixXd::Zero(62, 1);
  const std::string text = weightsCsvText({"jawOpen"}, w, 0, 60.0, WeightsCsvLayout::LiveLink);
  EXPECT_EQ(text.substr(0, text.find('\n')), "Timecode,BlendShapeCount,jawOpen");
  EXPECT_NE(text.find("\n00:00:00:59.000,1,0\n00:00:01:00.000,1,0\n00:00:01:01.000,1,0\n"), std::string::npos);
  // 29.97 Hz counts 30 frames a second; the sub-frame drift shows after the dot.
  const std::string ntsc = weightsCsvText({"jawOpen"}, Eigen::MatrixXd::Zero(31, 1), 0, 29.97, WeightsCsvLayout::LiveLink);
  EXPECT_NE(ntsc.find("\n00:00:01:00.030,1,0\n"), std::string::npos) << ntsc;
}

TEST(WeightsCsvWriter, RefusesMismatchedNamesAndRatesAndWritesAtomically)
{
  const Eigen::MatrixXd w = Eigen::MatrixXd::Zero(2, 2);
  EXPECT_THROW((void)weightsCsvText({"a"}, w, 0, 60.0, WeightsCsvLayout::Plain), InvalidArgument);
  EXPECT_THROW((void)weightsCsvText({"a", "b"}, w, 0, 0.0, WeightsCsvLayout::Plain), InvalidArgument);
  const test::TempDir dir;
  writeWeightsCsv(dir.file("w.csv"), {"a", "b"}, w, 1, 60.0, WeightsCsvLayout::Plain);
  EXPECT_EQ(readFileBytes(dir.file("w.csv")), "Frame,Time,a,b\n1,0,0,0\n2,0.016666666666666666,0,0\n");
  EXPECT_EQ(test::entryCount(dir.path()), 1u);
}

} // namespace
} // namespace mocap
