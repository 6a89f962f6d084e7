#include "mocap/io/live_link_face_csv.h"

#include "error_text.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

using test::errorOf;

std::string recordingText()
{
  return readFileBytes(test::dataFile("livelink_face/alex_rom_4_first200.csv"));
}

TEST(LiveLinkFaceCsv, ARealRecordingReadsAndWritesBackByteForByte)
{
  const std::string text = recordingText();
  const LiveLinkFaceRecording recording = parseLiveLinkFaceCsv(text, "alex_rom_4");
  ASSERT_EQ(recording.timecodes.size(), 200u);
  EXPECT_EQ(recording.timecodes.front(), "16:55:51:38.453");
  EXPECT_NEAR(recording.weights(0, 0), 0.1824302822, 1e-12) << "EyeBlinkLeft of the first row";
  EXPECT_NEAR(recording.rotations(0, 3), -0.0666924417, 1e-12) << "LeftEyeYaw of the first row";
  EXPECT_EQ(liveLinkFaceCsvText(recording), text) << "names, order, count, timecodes and the printed precision";
  EXPECT_EQ(liveLinkFaceRate(recording), 30.0) << "a row every second frame of the app's 60";
}

TEST(LiveLinkFaceCsv, TimecodesCountTheAppsSixtyFramesWithThousandths)
{
  EXPECT_NEAR(liveLinkFaceSeconds("16:55:51:38.453"), 16 * 3600 + 55 * 60 + 51 + (38 + 0.453) / 60.0, 1e-9);
  EXPECT_EQ(liveLinkFaceTimecode(0.0), "00:00:00:00.000");
  EXPECT_EQ(liveLinkFaceTimecode(1.0 / 60.0), "00:00:00:01.000");
  EXPECT_EQ(liveLinkFaceTimecode(0.01), "00:00:00:00.600") << "a 100 Hz take's second frame";
  EXPECT_EQ(liveLinkFaceTimecode(3725.5), "01:02:05:30.000");
  for (const char* bad : {"1:02:03:04.005", "00:00:00:60.000", "00:61:00:00.000", "00:00:00:00.000x", "junk"})
    EXPECT_THROW((void)liveLinkFaceSeconds(bad), InvalidArgument) << bad;
}

TEST(LiveLinkFaceCsv, ASolveUnderArkitNamesFillsTheAppsColumns)
{
  Eigen::MatrixXd weights(3, 2);
  weights << 0.0, 0.5, 0.25, 0.75, 1.0, 1.0;
  Eigen::MatrixXd head(3, 3);
  head << 0.1, 0.2, 0.3, 0.0, 0.0, 0.0, -0.1, -0.2, -0.3;
  const LiveLinkFaceRecording recording = liveLinkFaceRecording({"JawOpen", "MouthSmileLeft"}, weights, 100.0, head);
  EXPECT_EQ(recording.timecodes, (std::vector<std::string>{"00:00:00:00.000", "00:00:00:00.600", "00:00:00:01.200"}));
  const auto column = [](const std::string& name) {
    const auto& names = liveLinkFaceShapeNames();
    return std::find(names.begin(), names.end(), name) - names.begin();
  };
  EXPECT_EQ(recording.weights.col(column("JawOpen")), weights.col(0));
  EXPECT_EQ(recording.weights.col(column("MouthSmileLeft")), weights.col(1));
  EXPECT_EQ(recording.weights.sum(), weights.sum()) << "the shapes not given are 0";
  EXPECT_EQ(recording.rotations.leftCols(3), head);
  EXPECT_EQ(recording.rotations.rightCols(6).cwiseAbs().sum(), 0.0) << "the eyes are not solved";
  const std::string text = liveLinkFaceCsvText(recording);
  EXPECT_EQ(text.substr(0, text.find('\n')), recordingText().substr(0, recordingText().find('\n'))) << "the app's header";
  const std::string unknown = errorOf([&] {
    (void)liveLinkFaceRecording({"jawOpen", "MouthSmileLeft"}, weights, 100.0, Eigen::MatrixXd());
  });
  EXPECT_NE(unknown.find("'jawOpen' is not one of its 52 ARKit names"), std::string::npos) << unknown;
}

TEST(LiveLinkFaceCsv, ABrokenRecordingIsAClearErrorNamingTheLine)
{
  const std::string text = recordingText();
  const std::size_t headerEnd = text.find('\n');
  std::string missing = text;
  missing.replace(missing.find(",TongueOut"), 10, ",Tongue");
  EXPECT_NE(errorOf([&] { (void)parseLiveLinkFaceCsv(missing, "r.csv"); }).find("'Tongue' is not a Live Link Face column"),
            std::string::npos);
  std::string badValue = text;
  const std::size_t thirdLine = badValue.find('\n', badValue.find('\n', headerEnd + 1) + 1) + 1;
  badValue.replace(badValue.find(",61,", thirdLine) + 4, 12, "nan         ");
  const std::string value = errorOf([&] { (void)parseLiveLinkFaceCsv(badValue, "r.csv"); });
  EXPECT_NE(value.find("line 4"), std::string::npos) << value;
  const std::string firstRow = text.substr(0, text.find('\n', headerEnd + 1));
  const std::string shortRow = firstRow.substr(0, firstRow.rfind(',')) + "\n";  // its last value gone
  EXPECT_NE(errorOf([&] { (void)parseLiveLinkFaceCsv(shortRow, "r.csv"); }).find("line 2: 62 fields"), std::string::npos);
  EXPECT_NE(errorOf([&] { (void)parseLiveLinkFaceCsv("Frame,Time,jawOpen\n0,0,1\n", "r.csv"); })
                .find("starts with Timecode,BlendShapeCount"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { (void)parseLiveLinkFaceCsv("", "r.csv"); }).find("empty"), std::string::npos);
}

} // namespace
} // namespace mocap
