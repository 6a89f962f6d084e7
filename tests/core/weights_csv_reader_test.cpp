// Weight curves read back as weights_csv_writer writes them (mocap stream --weights).
#include "error_text.h"

#include "mocap/io/weights_csv_reader.h"
#include "mocap/io/weights_csv_writer.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

using test::errorOf;

TEST(WeightsCsvReader, ReadsBackWhatTheWriterWroteWithItsFramesAndRate)
{
  Eigen::MatrixXd w(4, 2);
  w << 0.0, 1.0, 0.25, 0.5, 0.125, 0.0, 1.0 / 3.0, 0.75;
  const WeightCurves curves = parseWeightsCsv(weightsCsvText({"jawOpen", "mouth,\"odd\""}, w, 10, 60.0), "w.csv");
  EXPECT_EQ(curves.names, (std::vector<std::string>{"jawOpen", "mouth,\"odd\""}));
  EXPECT_EQ(curves.firstFrame, 10);
  EXPECT_EQ(curves.frameRate, 60.0);
  EXPECT_EQ(curves.weights, w);
}

TEST(WeightsCsvReader, SaysWhichLineIsWrongAndWhy)
{
  EXPECT_NE(errorOf([] { (void)parseWeightsCsv("", "w.csv"); }).find("empty"), std::string::npos);
  EXPECT_NE(errorOf([] { (void)parseWeightsCsv("Timecode,BlendShapeCount,JawOpen\n", "w.csv"); })
                .find("start with Frame,Time"),
            std::string::npos);
  EXPECT_NE(errorOf([] { (void)parseWeightsCsv("Frame,Time,a\n1,0,0.5\n2,0.1\n", "w.csv"); }).find("line 3: 2 cells"),
            std::string::npos);
  EXPECT_NE(errorOf([] { (void)parseWeightsCsv("Frame,Time,a\n1,0,x\n", "w.csv"); }).find("'x' is not a finite"),
            std::string::npos);
  EXPECT_NE(errorOf([] { (void)parseWeightsCsv("Frame,Time,a\n1,0,nan\n", "w.csv"); }).find("'nan'"),
            std::string::npos);
  EXPECT_NE(errorOf([] { (void)parseWeightsCsv("Frame,Time,a\n1,0.1,0\n2,0.1,0\n", "w.csv"); })
                .find("line 3: the time does not increase"),
            std::string::npos);
  EXPECT_NE(errorOf([] { (void)parseWeightsCsv("Frame,Time,\"a\n", "w.csv"); }).find("not closed"), std::string::npos);
}

} // namespace
} // namespace mocap
