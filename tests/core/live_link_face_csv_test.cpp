#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/live_link_face_resample.h"

#include "error_text.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

TEST(LiveLinkFaceCsv, ARecordingsEyeRotationsAreWrittenBackAsGiven)
{
  Eigen::MatrixXd weights = Eigen::MatrixXd::Constant(2, 1, 0.5);
  Eigen::MatrixXd rotations(2, 9);
  rotations << 0.1, 0.2, 0.3, 0.01, 0.02, 0.03, -0.01, -0.02, -0.03,  //
      0.0, 0.0, 0.0, 0.12, -0.06, 0.0, 0.11, -0.07, 0.0;
  const LiveLinkFaceRecording recording = liveLinkFaceRecording({"JawOpen"}, weights, 60.0, rotations);
  EXPECT_EQ(recording.rotations, rotations) << "head, left eye, right eye in the app's order";
  const std::string wrong = errorOf([&] {
    (void)liveLinkFaceRecording({"JawOpen"}, weights, 60.0, Eigen::MatrixXd::Zero(2, 6));
  });
  EXPECT_NE(wrong.find("each eye's yaw, pitch and roll"), std::string::npos) << wrong;
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

/// One second at 30 Hz: JawOpen rising by 0.01 a row, EyeBlinkLeft held at 0.5, the head yawing
/// by 0.002 rad a row, so linear interpolation in time is exact.
LiveLinkFaceRecording resampleRampAt30Hz()
{
  Eigen::MatrixXd weights(31, 2), head = Eigen::MatrixXd::Zero(31, 3);
  for (Eigen::Index f = 0; f < 31; ++f) {
    weights(f, 0) = 0.01 * static_cast<double>(f);
    weights(f, 1) = 0.5;
    head(f, 0) = 0.002 * static_cast<double>(f);
  }
  return liveLinkFaceRecording({"JawOpen", "EyeBlinkLeft"}, weights, 30.0, head);
}

Eigen::Index liveLinkColumnOf(const std::string& name)
{
  const auto& names = liveLinkFaceShapeNames();
  return std::find(names.begin(), names.end(), name) - names.begin();
}

TEST(LiveLinkFaceResample, MeetsATakesFramesByTimecodeAndADroppedRowLeavesNoShift)
{
  const LiveLinkFaceRecording ramp = resampleRampAt30Hz();
  const Eigen::Index jaw = liveLinkColumnOf("JawOpen"), blink = liveLinkColumnOf("EyeBlinkLeft");
  // At a 100 Hz take's rate: 101 rows over the second, each on the straight line at k / 100 s.
  const LiveLinkFaceRecording take = resampleLiveLinkFace(ramp, 100.0);
  ASSERT_EQ(take.timecodes.size(), 101u);
  EXPECT_EQ(take.timecodes.front(), ramp.timecodes.front());
  EXPECT_EQ(take.timecodes.back(), ramp.timecodes.back());
  EXPECT_EQ(liveLinkFaceRate(take), 100.0);
  for (Eigen::Index k = 0; k < 101; ++k) {
    const double t = static_cast<double>(k) / 100.0;
    ASSERT_NEAR(take.weights(k, jaw), 0.3 * t, 1e-9) << "row " << k;
    ASSERT_NEAR(take.weights(k, blink), 0.5, 1e-12);
    ASSERT_NEAR(take.rotations(k, 0), 0.06 * t, 1e-9) << "HeadYaw, row " << k;
  }
  // At its own rate: the rows back.
  const LiveLinkFaceRecording same = resampleLiveLinkFace(ramp, 30.0);
  EXPECT_EQ(same.timecodes, ramp.timecodes);
  EXPECT_LT((same.weights - ramp.weights).cwiseAbs().maxCoeff(), 1e-12);

  // A row the app dropped is filled from its neighbours; the rows after it stay at their times.
  LiveLinkFaceRecording dropped = ramp;
  dropped.timecodes.erase(dropped.timecodes.begin() + 5);
  dropped.weights = Eigen::MatrixXd(30, ramp.weights.cols());
  dropped.weights << ramp.weights.topRows(5), ramp.weights.bottomRows(25);
  dropped.rotations = Eigen::MatrixXd(30, ramp.rotations.cols());
  dropped.rotations << ramp.rotations.topRows(5), ramp.rotations.bottomRows(25);
  const LiveLinkFaceRecording filled = resampleLiveLinkFace(dropped, 30.0);
  ASSERT_EQ(filled.timecodes, ramp.timecodes);
  EXPECT_LT((filled.weights - ramp.weights).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((filled.rotations - ramp.rotations).cwiseAbs().maxCoeff(), 1e-9);

  // A real recording (30 Hz, drifting by a thousandth of a frame now and then) at 100 Hz.
  const LiveLinkFaceRecording recording = parseLiveLinkFaceCsv(recordingText(), "alex_rom_4");
  const LiveLinkFaceRecording real = resampleLiveLinkFace(recording, 100.0);
  const double span = liveLinkFaceSeconds(recording.timecodes.back()) - liveLinkFaceSeconds(recording.timecodes.front());
  EXPECT_EQ(static_cast<double>(real.timecodes.size()), std::floor(span * 100.0) + 1.0);
  EXPECT_EQ(real.timecodes.front(), recording.timecodes.front());
  EXPECT_LT((real.weights.row(0) - recording.weights.row(0)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GE(real.weights.minCoeff(), recording.weights.minCoeff());
  EXPECT_LE(real.weights.maxCoeff(), recording.weights.maxCoeff());

  // Bad input: a clear error naming what is wrong.
  EXPECT_NE(errorOf([&] { (void)resampleLiveLinkFace(ramp, 0.0); }).find("rate"), std::string::npos);
  LiveLinkFaceRecording one = ramp;
  one.timecodes.resize(1);
  one.weights.conservativeResize(1, Eigen::NoChange);
  one.rotations.conservativeResize(1, Eigen::NoChange);
  EXPECT_NE(errorOf([&] { (void)resampleLiveLinkFace(one, 30.0); }).find("two rows"), std::string::npos);
  LiveLinkFaceRecording backwards = ramp;
  std::swap(backwards.timecodes[3], backwards.timecodes[4]);
  EXPECT_NE(errorOf([&] { (void)resampleLiveLinkFace(backwards, 30.0); }).find("row 5"), std::string::npos);
}
} // namespace
} // namespace mocap
