#include "mocap/io/trc_io.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using mocap::test::TempDir;

// Whether any warning holds `needle`. O(total warning length).
bool contains(const std::vector<std::string>& warnings, const std::string& needle)
{
  for (const std::string& warning : warnings)
    if (warning.find(needle) != std::string::npos)
      return true;
  return false;
}

// Parses and reports how: "ok", "format" (FormatError) or the surprise. O(text size).
std::string parseOutcome(const std::string& text)
{
  try {
    std::vector<std::string> warnings;
    (void)mocap::parseTrc(text, "fuzz.trc", &warnings);
    return "ok";
  } catch (const mocap::FormatError&) {
    return "format";
  } catch (const std::exception& e) {
    return std::string("unexpected exception: ") + e.what();
  }
}

// Four frames of three markers (labels with a space and a colon), one gap. O(1).
mocap::Take smallTake()
{
  mocap::Take take({"Nose Tip", "L:Cheek", "Chin"}, 4, 120.0);
  take.setFirstFrame(100);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      const Eigen::Vector3d p(1.5 * static_cast<double>(f), -2.25, 10.0 * static_cast<double>(m));
      take.setPosition(f, m, p);
      take.valid()(f, m) = true;
      take.residuals()(f, m) = 0.0;
    }
  }
  take.valid()(2, 1) = false;
  return take;
}

const char* const kSmallText = "PathFileType\t4\t(X/Y/Z)\tsmall.trc\n"
                               "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n"
                               "100\t100\t3\t2\tmm\n"
                               "Frame#\tTime\tA\t\t\tB\t\t\n"
                               "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n"
                               "\n"
                               "1\t0\t1\t2\t3\t4\t5\t6\n"
                               "2\t0.01\t1.5\t2.5\t3.5\t\t\t\n"
                               "3\t0.02\t0\t0\t0\tNaN\tnan\tNaN\n";

} // namespace

TEST(TrcIo, ReadsNoseMoCap)
{
  std::vector<std::string> warnings;
  const mocap::Take take = mocap::readTrc(mocap::test::dataFile("trc/NoseMoCap.trc"), &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_EQ(take.markerCount(), 41);
  ASSERT_EQ(take.frameCount(), 962);
  EXPECT_EQ(take.frameRate(), 60.0);
  EXPECT_EQ(take.units(), mocap::LengthUnit::Millimetre);
  EXPECT_EQ(take.firstFrame(), 1);
  EXPECT_EQ(take.label(0), "ForeHead_M");
  EXPECT_EQ(take.label(20), "Reye_Inside");
  EXPECT_EQ(take.label(40), "Chin_L2");
  EXPECT_EQ(take.validFraction(), 1.0);
  EXPECT_TRUE((take.residuals() == 0.0).all());
  EXPECT_EQ(take.state(0, 0), mocap::SampleOrigin::Measured);

  // Values copied from the file's text (frame 1, 494 and 962).
  EXPECT_EQ(take.position(0, 0), Eigen::Vector3d(143.52007, 842.21375, 29.05422));
  EXPECT_EQ(take.position(493, 20), Eigen::Vector3d(122.62377, 765.05310, 44.34309));
  EXPECT_EQ(take.position(961, 40), Eigen::Vector3d(192.75803, 685.83356, -4.35550));
}

TEST(TrcIo, WriteReadRoundTripIsExact)
{
  mocap::Take take({"Nose Tip", "L:Cheek", "Chin", "Never"}, 9, 59.94);
  take.setFirstFrame(-3);
  take.setUnits(mocap::LengthUnit::Centimetre);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> value(-1e3, 1e3);  // within a capture volume: no unit warning
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    for (Eigen::Index m = 0; m < 3; ++m) {
      // Float values as a float C3D holds them, plus full doubles and awkward magnitudes.
      const Eigen::Vector3d p(static_cast<double>(static_cast<float>(value(random))), value(random),
                              f == 4 ? 1e-300 : 0.1 + 0.2);
      take.setPosition(f, m, p);
      take.valid()(f, m) = (f + m) % 4 != 1;
      take.residuals()(f, m) = take.valid()(f, m) ? 0.0 : -1.0;
    }
  }
  take.setPosition(0, 0, Eigen::Vector3d(0.0, 0.0, 0.0));  // zeros are a real sample, not a gap
  take.valid()(0, 0) = true;
  take.residuals()(0, 0) = 0.0;

  const TempDir dir;
  const fs::path file = dir.path() / "round trip.trc";
  mocap::writeTrc(take, file);
  const std::string text = mocap::readFileBytes(file);
  EXPECT_EQ(text.rfind("PathFileType\t4\t(X/Y/Z)\tround trip.trc\n", 0), 0U);

  std::vector<std::string> warnings;
  const mocap::Take back = mocap::readTrc(file, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(back.labels(), take.labels());
  EXPECT_EQ(back.frameRate(), 59.94);
  EXPECT_EQ(back.firstFrame(), -3);
  EXPECT_EQ(back.units(), mocap::LengthUnit::Centimetre);
  ASSERT_EQ(back.frameCount(), take.frameCount());
  ASSERT_EQ(back.markerCount(), take.markerCount());
  EXPECT_TRUE((back.valid() == take.valid()).all());
  EXPECT_TRUE((back.residuals() == take.residuals()).all());
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    for (Eigen::Index m = 0; m < take.markerCount(); ++m)
      if (take.isValid(f, m)) {
        EXPECT_EQ(back.position(f, m), take.position(f, m)) << "frame " << f << " marker " << m;
      }
  EXPECT_FALSE(back.valid().col(3).any());
}

TEST(TrcIo, MissingSamplesAreEmptyCells)
{
  const std::string text = mocap::formatTrc(smallTake(), "small.trc");
  EXPECT_NE(text.find("Frame#\tTime\tNose Tip\t\t\tL:Cheek\t\t\tChin\t\t\n"
                      "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\tX3\tY3\tZ3\n\n"),
            std::string::npos);
  EXPECT_NE(text.find("\n102\t0.016666666666666666\t3\t-2.25\t0\t\t\t\t3\t-2.25\t20\n"), std::string::npos);
  EXPECT_NE(text.find("\n120\t120\t4\t3\tmm\t120\t100\t4\n"), std::string::npos);
}

TEST(TrcIo, ToleratesCrlfBlanksShortRowsAndNaN)
{
  const std::string text = "PathFileType  4 (X/Y/Z)  messy.trc\r\n"
                           "DataRate CameraRate\tNumFrames  NumMarkers\tUnits\t\r\n"
                           "250  250\t5 2\tm\t\t\r\n"
                           "Frame#\tTime\tHead Top\t\t\tJaw\t\t\t\t\r\n"
                           "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\t\r\n"
                           "\r\n"
                           "7\t0\t1\t2\t3\t4\t5\t6\t\t\r\n"
                           "8\t0.004\t0\t0\t0\tNaN\tnan\tNaN\r\n"
                           "9\t0.008\t1.5\t+2.5\t-3.5e-2\r\n"
                           "10\t0.012\t1\t\t3\t4\t5\t6\r\n";
  std::vector<std::string> warnings;
  const mocap::Take take = mocap::parseTrc(text, "messy.trc", &warnings);
  ASSERT_EQ(take.frameCount(), 4);
  ASSERT_EQ(take.markerCount(), 2);
  EXPECT_EQ(take.label(0), "Head Top");
  EXPECT_EQ(take.label(1), "Jaw");
  EXPECT_EQ(take.frameRate(), 250.0);
  EXPECT_EQ(take.units(), mocap::LengthUnit::Metre);
  EXPECT_EQ(take.firstFrame(), 7);
  EXPECT_TRUE(contains(warnings, "NumFrames is 5 but the file has 4 data rows")) << warnings.size();

  EXPECT_EQ(take.position(0, 1), Eigen::Vector3d(4, 5, 6));
  EXPECT_TRUE(take.isValid(1, 0));
  EXPECT_EQ(take.position(1, 0), Eigen::Vector3d(0, 0, 0));
  EXPECT_FALSE(take.isValid(1, 1));
  EXPECT_EQ(take.residuals()(1, 1), -1.0);
  EXPECT_EQ(take.position(2, 0), Eigen::Vector3d(1.5, 2.5, -3.5e-2));
  EXPECT_FALSE(take.isValid(2, 1));  // short row
  EXPECT_FALSE(take.isValid(3, 0));  // one empty coordinate
  EXPECT_TRUE(take.isValid(3, 1));
}

TEST(TrcIo, DuplicateAndMissingLabelsAreRenamedWithWarnings)
{
  const std::string text = "PathFileType\t4\t(X/Y/Z)\tdup.trc\n"
                           "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n"
                           "100\t100\t1\t4\tfurlongs\n"
                           "Frame#\tTime\tA\t\t\tA\t\t\tA\t\t\t\t\t\n"
                           "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\tX3\tY3\tZ3\tX4\tY4\tZ4\n"
                           "1\t0\t1\t1\t1\t2\t2\t2\t3\t3\t3\t4\t4\t4\n";
  std::vector<std::string> warnings;
  const mocap::Take take = mocap::parseTrc(text, "dup.trc", &warnings);
  EXPECT_EQ(take.labels(), (std::vector<std::string>{"A", "A_2", "A_3", "M4"}));
  EXPECT_TRUE(contains(warnings, "duplicate marker label 'A' renamed to 'A_2'"));
  EXPECT_TRUE(contains(warnings, "duplicate marker label 'A' renamed to 'A_3'"));
  EXPECT_TRUE(contains(warnings, "has no label; named M4"));
  EXPECT_TRUE(contains(warnings, "unknown Units 'furlongs'; assuming mm"));
  EXPECT_EQ(take.units(), mocap::LengthUnit::Millimetre);
  EXPECT_EQ(take.position(0, 3), Eigen::Vector3d(4, 4, 4));
}

TEST(TrcIo, SmallTextParses)
{
  const mocap::Take take = mocap::parseTrc(kSmallText, "small.trc");
  ASSERT_EQ(take.frameCount(), 3);
  EXPECT_TRUE(take.isValid(2, 0));
  EXPECT_FALSE(take.isValid(2, 1));
  EXPECT_FALSE(take.isValid(1, 1));
  EXPECT_EQ(take.position(1, 0), Eigen::Vector3d(1.5, 2.5, 3.5));
}

TEST(TrcIo, MalformedInputThrowsFormatErrorWithLine)
{
  const auto messageOf = [](const std::string& text) -> std::string {
    try {
      (void)mocap::parseTrc(text, "bad.trc");
    } catch (const mocap::FormatError& e) {
      EXPECT_EQ(e.file(), "bad.trc");
      return e.what();
    }
    return "no error";
  };
  const std::string header = "PathFileType\t4\t(X/Y/Z)\tbad.trc\nDataRate\tNumFrames\tNumMarkers\tUnits\n";
  EXPECT_NE(messageOf("").find("line 1: not a TRC file"), std::string::npos);
  EXPECT_NE(messageOf("hello\nworld\n").find("line 1"), std::string::npos);
  EXPECT_NE(messageOf(header).find("line 3: file ends inside the header"), std::string::npos);
  EXPECT_NE(messageOf(header + "100\t1\tmany\tmm\nFrame#\tTime\tA\n").find("line 3: no valid NumMarkers"),
            std::string::npos);
  EXPECT_NE(messageOf(header + "-5\t1\t1\tmm\nFrame#\tTime\tA\n").find("line 3: no valid DataRate"),
            std::string::npos);
  EXPECT_NE(messageOf(header + "100\t1\t2000000000\tmm\nFrame#\tTime\tA\n").find("too large"),
            std::string::npos);
  EXPECT_NE(messageOf(header + "100\t1\t1\tmm\n").find("line 4"), std::string::npos);
  const std::string body = header + "100\t2\t1\tmm\nFrame#\tTime\tA\n\t\tX1\tY1\tZ1\n\n1\t0\t1\t2\t3\n";
  EXPECT_NE(messageOf(body + "2\t0.01\t1\tabc\t3\n").find("line 8: bad number 'abc' in column 4"),
            std::string::npos);
  EXPECT_NE(messageOf(body + "x\t0.01\t1\t2\t3\n").find("line 8: bad frame number"), std::string::npos);
  EXPECT_NE(messageOf(body + "99999999999999999999\t0.01\t1\t2\t3\n").find("line 8"), std::string::npos);
}

TEST(TrcIo, HostileCountsAreRejectedQuickly)
{
  // 20000 copies of one label (renaming must stay linear) and many empty rows: the sample count
  // far exceeds what the text can hold, so parsing must refuse before allocating the take.
  std::string text = "PathFileType\t4\t(X/Y/Z)\th.trc\n"
                     "DataRate\tNumFrames\tNumMarkers\tUnits\n100\t1\t20000\tmm\nFrame#\tTime";
  for (int i = 0; i < 20000; ++i)
    text += "\tA\t\t";
  text += "\n\t\n";
  for (int i = 0; i < 20000; ++i)
    text += std::to_string(i + 1) + "\n";
  EXPECT_THROW((void)mocap::parseTrc(text, "h.trc"), mocap::FormatError);

  // The same labels with a single row are fine and get unique names.
  const std::string single = text.substr(0, text.find("\n2\n") + 1);
  const mocap::Take take = mocap::parseTrc(single, "h.trc");
  EXPECT_EQ(take.markerCount(), 20000);
  EXPECT_EQ(take.label(19999), "A_20000");
}

TEST(TrcIo, EveryTruncationParsesOrThrowsFormatError)
{
  const std::string texts[] = {std::string(kSmallText), mocap::formatTrc(smallTake(), "t.trc")};
  for (const std::string& text : texts) {
    for (std::size_t length = 0; length <= text.size(); ++length) {
      const std::string outcome = parseOutcome(text.substr(0, length));
      ASSERT_TRUE(outcome == "ok" || outcome == "format") << "length " << length << ": " << outcome;
    }
    EXPECT_EQ(parseOutcome(text), "ok");
  }
}

TEST(TrcIo, RandomByteFlipsNeverCrash)
{
  const std::string base = mocap::formatTrc(smallTake(), "t.trc");
  const char interesting[] = {'\t', '\n', '\r', ' ', '0', '9', '-', '.', 'e', 'n', '\0', '\xff'};
  std::mt19937 random(12345);
  std::uniform_int_distribution<std::size_t> position(0, base.size() - 1);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<std::size_t> pick(0, sizeof interesting - 1);
  int parsed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text = base;
    const int flips = 1 + trial % 4;
    for (int i = 0; i < flips; ++i)
      text[position(random)] = trial % 2 == 0 ? static_cast<char>(byte(random)) : interesting[pick(random)];
    const std::string outcome = parseOutcome(text);
    ASSERT_TRUE(outcome == "ok" || outcome == "format") << "trial " << trial << ": " << outcome;
    parsed += outcome == "ok" ? 1 : 0;
  }
  EXPECT_GT(parsed, 0);  // the tolerant reader accepts many small damages
}
