// C3D reader against the c3d.org and vendor samples in tests/data/c3d (see tests/data/SOURCES.md).
#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/model/gaps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace mocap {
namespace {

using test::dataFile;

struct Expected
{
  const char* file;
  Eigen::Index markers;
  Eigen::Index frames;
  double rate;
  std::int64_t firstFrame;
};

// Counts from the sources table (tests/data/SOURCES.md), which an independent reader produced.
const Expected kValidFiles[] = {
    {"c3d/sample01/Eb015pi.c3d", 26, 450, 50.0, 1},
    {"c3d/sample01/Eb015pr.c3d", 26, 450, 50.0, 1},
    {"c3d/sample01/Eb015si.c3d", 26, 450, 50.0, 1},
    {"c3d/sample01/Eb015sr.c3d", 26, 450, 50.0, 1},
    {"c3d/sample01/Eb015vi.c3d", 26, 450, 50.0, 1},
    {"c3d/sample01/Eb015vr.c3d", 26, 450, 50.0, 1},
    {"c3d/sample02/pc_int.c3d", 36, 89, 50.0, 1},
    {"c3d/sample02/pc_real.c3d", 36, 89, 50.0, 1},
    {"c3d/sample02/sgi_int.c3d", 36, 89, 50.0, 1},
    {"c3d/sample02/sgi_real.c3d", 36, 89, 50.0, 1},
    {"c3d/sample02/dec_int.c3d", 36, 89, 50.0, 1},
    {"c3d/sample02/dec_real.c3d", 36, 89, 50.0, 1},
    {"c3d/sample03/gait-pig-nz.c3d", 85, 301, 120.0, 300},
    {"c3d/sample08/TESTAPI.c3d", 26, 450, 50.0, 1},
    {"c3d/sample08/TESTBPI.c3d", 26, 450, 50.0, 1},
    {"c3d/sample08/TESTCPI.c3d", 26, 450, 50.0, 1},
    {"c3d/sample08/TESTDPI.c3d", 26, 450, 50.0, 1},
    {"c3d/sample13/Dance.c3d", 40, 499, 65.053, 1},
    {"c3d/sample16/basketball.c3d", 22, 34, 25.0, 1},
    {"c3d/sample37/ART-Human_tools_integer_6dofLimbs.c3d", 37, 1162, 60.0, 1},
    {"c3d/sample00_motion_analysis/Walk1.c3d", 49, 151, 60.0, 1},
    {"c3d/btk_others/mocap36.c3d", 36, 1380, 100.0, 1},
};

class C3dValidFile : public ::testing::TestWithParam<Expected>
{
};

TEST_P(C3dValidFile, LoadsWithTheDocumentedShape)
{
  const Expected& e = GetParam();
  std::vector<std::string> warnings;
  const Take take = readC3d(dataFile(e.file), &warnings);
  EXPECT_EQ(take.markerCount(), e.markers);
  EXPECT_EQ(take.frameCount(), e.frames);
  EXPECT_NEAR(take.frameRate(), e.rate, 1e-3);
  EXPECT_EQ(take.firstFrame(), e.firstFrame);
  EXPECT_EQ(take.valid().rows(), e.frames);
  EXPECT_EQ(take.valid().cols(), e.markers);
  EXPECT_FALSE(take.parameters().empty());
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    EXPECT_FALSE(take.label(m).empty());
  // Invalid samples always carry residual -1; valid ones a non-negative residual.
  EXPECT_TRUE(((take.residuals() < 0.0) == !take.valid()).all());
}

INSTANTIATE_TEST_SUITE_P(AllConformanceFiles, C3dValidFile, ::testing::ValuesIn(kValidFiles),
                         [](const ::testing::TestParamInfo<Expected>& param) {
                           std::string name = std::filesystem::path(param.param.file).stem().string();
                           std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
                           return name;
                         });

TEST(C3dReader, BundledFacialTakeHasItsDocumentedGaps)
{
  std::vector<std::string> warnings;
  const Take take = readC3d(test::sampleTake(), &warnings);
  EXPECT_EQ(take.markerCount(), 38);
  EXPECT_EQ(take.frameCount(), 3000);
  EXPECT_DOUBLE_EQ(take.frameRate(), 100.0);
  EXPECT_EQ(take.units(), LengthUnit::Millimetre);
  EXPECT_EQ(take.analog().channelCount(), 0);
  EXPECT_NEAR(take.validFraction(), 0.967, 0.0015);
  const auto marker = take.markerIndex("section3-1");
  ASSERT_TRUE(marker.has_value());
  const auto gaps = findGaps(take.valid().col(*marker), *marker);
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_EQ(take.firstFrame() + gaps[0].firstFrame, 887);
  EXPECT_EQ(gaps[0].length, 919 - 887 + 1);
  const auto root = take.markerIndex("root-1");
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(take.valid().col(*root).all());
}

// Exact values published by OpenMA's C3D handler tests for the sample01 set.
void expectSample01Values(const Take& take, double tolerance)
{
  const auto rft1 = take.markerIndex("RFT1");
  ASSERT_TRUE(rft1.has_value());
  EXPECT_NEAR(take.trajectory(*rft1)(8, 0), 250.4166, tolerance);
  EXPECT_NEAR(take.residuals()(0, *rft1), 1.3333, tolerance);
  EXPECT_NEAR(take.residuals()(20, 14), 1.91667, tolerance);
  EXPECT_NEAR(take.trajectory(17)(16, 0), 285.0, tolerance);
  EXPECT_NEAR(take.trajectory(17)(16, 1), 222.4166, tolerance);
  EXPECT_NEAR(take.trajectory(17)(16, 2), 564.4166, tolerance);
  const AnalogData& analog = take.analog();
  ASSERT_EQ(analog.channelCount(), 16);
  EXPECT_EQ(analog.sampleCount(), 450 * 4);
  EXPECT_DOUBLE_EQ(analog.rate, 200.0);
  const Eigen::VectorXd first = analog.physical(0);
  EXPECT_NEAR(first(0), -26.6599, 1e-3);
  EXPECT_NEAR(first(1), -25.8, tolerance);
  EXPECT_EQ(analog.channels[2].description, "FORCE Z-COMP 1");
  EXPECT_EQ(analog.channels[15].label, "CH16");
  ASSERT_EQ(take.events().size(), 3u);
  EXPECT_EQ(take.events()[0].label, "RIC");
  EXPECT_NEAR(take.events()[0].time, 2.72, 1e-4);
  EXPECT_EQ(take.events()[1].label, "RHS");
  EXPECT_NEAR(take.events()[1].time, 5.40, 1e-4);
  EXPECT_EQ(take.events()[2].label, "RTO");
  EXPECT_NEAR(take.events()[2].time, 7.32, 1e-4);
}

TEST(C3dReader, Sample01ExactValuesInEveryProcessorAndStorage)
{
  for (const char* name : {"Eb015pi", "Eb015pr", "Eb015si", "Eb015sr", "Eb015vi", "Eb015vr"}) {
    SCOPED_TRACE(name);
    expectSample01Values(readC3d(dataFile(std::string("c3d/sample01/") + name + ".c3d")), 1e-4);
  }
}

/// Largest |a − b| over samples valid in both, after checking the masks are identical.
double maxPositionDifference(const Take& a, const Take& b)
{
  EXPECT_EQ(a.labels(), b.labels());
  EXPECT_TRUE((a.valid() == b.valid()).all());
  double worst = 0.0;
  for (Eigen::Index m = 0; m < a.markerCount(); ++m)
    for (Eigen::Index f = 0; f < a.frameCount(); ++f)
      if (a.isValid(f, m) && b.isValid(f, m))
        worst = std::max(worst, (a.position(f, m) - b.position(f, m)).cwiseAbs().maxCoeff());
  return worst;
}

TEST(C3dReader, SixVariantsOfSample01GiveTheSamePoints)
{
  const Take reference = readC3d(dataFile("c3d/sample01/Eb015pr.c3d"));
  const double scale = 0.0833;  // integer storage quantum (POINT:SCALE)
  for (const char* name : {"Eb015pi", "Eb015si", "Eb015sr", "Eb015vi", "Eb015vr"}) {
    SCOPED_TRACE(name);
    const Take other = readC3d(dataFile(std::string("c3d/sample01/") + name + ".c3d"));
    EXPECT_LE(maxPositionDifference(reference, other), scale / 2);
    EXPECT_LE((reference.residuals() - other.residuals()).abs().maxCoeff(), scale / 2);
    EXPECT_LE((reference.analog().stored - other.analog().stored).cwiseAbs().maxCoeff(), 0.5);
  }
}

TEST(C3dReader, SixVariantsOfSample02GiveTheSamePoints)
{
  const Take reference = readC3d(dataFile("c3d/sample02/pc_real.c3d"));
  const double scale = std::abs(readC3d(dataFile("c3d/sample02/pc_int.c3d")).parameters().number("POINT", "SCALE").value());
  for (const char* name : {"pc_int", "sgi_int", "sgi_real", "dec_int", "dec_real"}) {
    SCOPED_TRACE(name);
    const Take other = readC3d(dataFile(std::string("c3d/sample02/") + name + ".c3d"));
    EXPECT_LE(maxPositionDifference(reference, other), scale + 1e-4);  // one storage quantum
  }
}

TEST(C3dReader, PhoenixFileWithZeroDataStartAndOddRate)
{
  std::vector<std::string> warnings;
  const Take take = readC3d(dataFile("c3d/sample13/Dance.c3d"), &warnings);
  EXPECT_EQ(take.analog().channelCount(), 8);
  EXPECT_EQ(take.analog().sampleCount(), take.frameCount());
  EXPECT_NEAR(take.frameRate(), 65.053, 1e-3);
  EXPECT_EQ(take.label(0), "Channel101");
  // Its POINT:FRAMES (500) also disagrees with the header's 499 frames, which the data hold exactly.
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("POINT:FRAMES (500) differs from the header's frame count (499)"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[1].find("DATA_START is 0"), std::string::npos) << warnings[1];
  EXPECT_EQ(take.validFraction(), 1.0);
}

TEST(C3dReader, AnalogValuesWithoutAnAnalogGroupGetGenericChannels)
{
  // Remove the ANALOG group of Eb015pr by renaming it: the header still declares 64 values per frame.
  std::string bytes = readFileBytes(dataFile("c3d/sample01/Eb015pr.c3d"));
  const auto at = bytes.find("ANALOG", 512);
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at, 6, "ANALOX");
  std::vector<std::string> warnings;
  const Take take = parseC3d(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "x.c3d", &warnings);
  EXPECT_EQ(take.analog().channelCount() * take.analog().sampleCount(), 64 * 450);
  EXPECT_EQ(take.analog().channels[0].label, "A1");
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(),
                          [](const std::string& w) { return w.find("no ANALOG group") != std::string::npos; }));
}

TEST(C3dReader, SimiFileWithEveryPointInvalidAndNoUnits)
{
  std::vector<std::string> warnings;
  const Take take = readC3d(dataFile("c3d/sample16/basketball.c3d"), &warnings);
  EXPECT_EQ(take.validFraction(), 0.0);
  EXPECT_EQ(take.analog().channelCount(), 0);
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(),
                          [](const std::string& w) { return w.find("POINT:UNITS is missing") != std::string::npos; }));
}

TEST(C3dReader, OptiTrackLabelsMissingTheirDescriptionByte)
{
  std::vector<std::string> warnings;
  const Take take = readC3d(dataFile("c3d/btk_others/mocap36.c3d"), &warnings);
  EXPECT_EQ(take.label(0), "Skeleton_Hip2");
  EXPECT_EQ(take.label(1), "Skeleton_Hip1");
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) {
    return w.find("LABELS") != std::string::npos && w.find("description-length") != std::string::npos;
  }));
  // All markers are lost from frame 1152 on (trailing data loss in the original capture).
  EXPECT_FALSE(take.valid().bottomRows(1380 - 1151).any());
  EXPECT_TRUE(take.valid().topRows(1151).any());
}

TEST(C3dReader, DuplicateLabelsGetASuffixAndAWarning)
{
  std::vector<std::string> warnings;
  const Take take = readC3d(dataFile("c3d/sample00_motion_analysis/Walk1.c3d"), &warnings);
  std::vector<std::string> labels = take.labels();
  std::sort(labels.begin(), labels.end());
  EXPECT_EQ(std::adjacent_find(labels.begin(), labels.end()), labels.end());
  EXPECT_TRUE(take.markerIndex("RKNE_2").has_value());
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(),
                          [](const std::string& w) { return w.find("duplicate marker label 'RKNE'") != std::string::npos; }));
}

TEST(C3dReader, ArtFileWithTwoDimensionalUnits)
{
  const Take take = readC3d(dataFile("c3d/sample37/ART-Human_tools_integer_6dofLimbs.c3d"));
  EXPECT_EQ(take.units(), LengthUnit::Millimetre);
  EXPECT_EQ(take.validFraction(), 1.0);
}

TEST(C3dReader, CorruptParameterSectionIsRejectedWithAClearError)
{
  const test::TempDir dir;
  test::writeCorruptC3d(dir.file("corrupt.c3d"));
  try {
    (void)readC3d(dir.file("corrupt.c3d"));
    FAIL() << "the corrupt file was accepted";
  } catch (const FormatError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("corrupt.c3d: parameter section corrupt: a record name is binary data"), std::string::npos)
        << message;
    EXPECT_GT(e.offset(), 512);
  }
}

TEST(C3dReader, ALastParameterRunningIntoTheDataIsLeftOutAndTheTakeReads)
{
  // c3d.org's sample18: 12 parameter blocks declared where the data starts after 10, and
  // EVENT:LABELS, the last record, runs into the data. Read to the data start, that one left out.
  std::vector<std::string> warnings;
  const Take take = readC3d(dataFile("c3d/sample18/bad_parameter_section.c3d"), &warnings);
  EXPECT_EQ(take.markerCount(), 45);
  EXPECT_EQ(take.frameCount(), 332);
  EXPECT_EQ(take.label(0), "P1");
  EXPECT_EQ(take.label(44), "P45");
  EXPECT_EQ(take.frameRate(), 120.0);
  EXPECT_EQ(take.analog().channelCount(), 32);
  const auto said = [&](const std::string& text) {
    return std::any_of(warnings.begin(), warnings.end(), [&](const std::string& w) { return w.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(said("parameter 'EVENT:LABELS' runs past the parameter section into the data section (byte 5632); left out"));
  EXPECT_FALSE(said("jump by over half")) << "the data start is the header's: no frame is shifted";
  EXPECT_EQ(take.parameters().find("EVENT", "LABELS"), nullptr);
  EXPECT_NE(take.parameters().find("EVENT", "CONTEXTS"), nullptr) << "the records before it are kept";
}

TEST(C3dReader, MissingFileAndNonC3dGiveClearErrors)
{
  EXPECT_THROW((void)readC3d(dataFile("c3d/no_such_file.c3d")), IoError);
  const std::string text(600, 'x');
  EXPECT_THROW((void)parseC3d(reinterpret_cast<const unsigned char*>(text.data()), text.size(), "text.c3d"),
               FormatError);
  EXPECT_THROW((void)parseC3d(nullptr, 0, "empty.c3d"), FormatError);
}

} // namespace
} // namespace mocap
