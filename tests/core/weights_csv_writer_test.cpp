// Blendshape-weight CSV: the plain Frame,Time layout (Live Link Face's is live_link_face_csv_test).
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
  EXPECT_EQ(weightsCsvText({"jawOpen", "mouth,odd"}, w, 10, 4.0),
            "Frame,Time,jawOpen,\"mouth,odd\"\n10,0,0,1\n11,0.25,0.25,0.5\n12,0.5,0.125,0\n");
}

TEST(WeightsCsvWriter, RefusesMismatchedNamesAndRatesAndWritesAtomically)
{
  const Eigen::MatrixXd w = Eigen::MatrixXd::Zero(2, 2);
  EXPECT_THROW((void)weightsCsvText({"a"}, w, 0, 60.0), InvalidArgument);
  EXPECT_THROW((void)weightsCsvText({"a", "b"}, w, 0, 0.0), InvalidArgument);
  const test::TempDir dir;
  writeWeightsCsv(dir.file("w.csv"), {"a", "b"}, w, 1, 60.0);
  EXPECT_EQ(readFileBytes(dir.file("w.csv")), "Frame,Time,a,b\n1,0,0,0\n2,0.016666666666666666,0,0\n");
  EXPECT_EQ(test::entryCount(dir.path()), 1u);
}

} // namespace
} // namespace mocap
