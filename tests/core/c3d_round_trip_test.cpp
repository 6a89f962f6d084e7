// C3D -> C3D and C3D -> TRC -> C3D keep every sample, gap, residual, camera mask, label, rate,
// first frame, analog value and event.
#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/model/marker_edits.h"
#include "mocap/model/marker_points.h"
#include "mocap/io/c3d_writer.h"
#include "mocap/base/error.h"
#include "mocap/io/trc_io.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mocap {
namespace {

using test::dataFile;

Take reparse(const Take& take)
{
  const std::string bytes = encodeC3d(take);
  std::vector<std::string> warnings;
  Take back = parseC3d(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "round-trip.c3d", &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  return back;
}

bool isFloatFile(const Take& take)
{
  return take.parameters().number("POINT", "SCALE").value_or(-1.0) < 0.0;
}

void expectSameTake(const Take& a, const Take& b, bool exactPositions)
{
  ASSERT_EQ(a.labels(), b.labels());
  ASSERT_EQ(a.frameCount(), b.frameCount());
  EXPECT_DOUBLE_EQ(static_cast<double>(static_cast<float>(a.frameRate())), b.frameRate());
  EXPECT_EQ(a.firstFrame(), b.firstFrame());
  EXPECT_EQ(a.units(), b.units());
  ASSERT_TRUE((a.valid() == b.valid()).all()) << "gaps changed";
  for (Eigen::Index m = 0; m < a.markerCount(); ++m)
    for (Eigen::Index f = 0; f < a.frameCount(); ++f) {
      if (!a.isValid(f, m))
        continue;
      const Eigen::Vector3d pa = a.position(f, m), pb = b.position(f, m);
      if (exactPositions)
        ASSERT_EQ(pa, pb) << a.label(m) << " frame " << f;
      else
        ASSERT_LE((pa - pb).cwiseAbs().maxCoeff(), 1e-6 * (1.0 + pa.cwiseAbs().maxCoeff())) << a.label(m);
    }
  EXPECT_TRUE((a.residuals() == b.residuals()).all()) << "residuals changed";
  EXPECT_TRUE((a.cameraMasks() == b.cameraMasks()).all()) << "camera masks changed";
  EXPECT_EQ(a.analog().stored, b.analog().stored);
  EXPECT_EQ(a.analog().channelCount(), b.analog().channelCount());
  for (std::size_t c = 0; c < a.analog().channels.size(); ++c) {
    EXPECT_EQ(a.analog().channels[c].label, b.analog().channels[c].label);
    EXPECT_FLOAT_EQ(static_cast<float>(a.analog().channels[c].scale), static_cast<float>(b.analog().channels[c].scale));
    EXPECT_EQ(a.analog().channels[c].offset, b.analog().channels[c].offset);
  }
  ASSERT_EQ(a.events().size(), b.events().size());
  for (std::size_t i = 0; i < a.events().size(); ++i) {
    EXPECT_EQ(a.events()[i].label, b.events()[i].label);
    EXPECT_EQ(a.events()[i].context, b.events()[i].context);
    EXPECT_NEAR(a.events()[i].time, b.events()[i].time, 1e-4);
  }
}

class C3dRoundTrip : public ::testing::TestWithParam<const char*>
{
};

TEST_P(C3dRoundTrip, WriteThenReadKeepsEverything)
{
  const Take original = readC3d(dataFile(GetParam()));
  const Take back = reparse(original);
  expectSameTake(original, back, isFloatFile(original));
  // Parameters the data do not define survive untouched.
  for (const C3dGroup& group : original.parameters().groups())
    for (const C3dParameter& p : group.parameters)
      EXPECT_NE(back.parameters().find(group.name, p.name), nullptr) << group.name << ":" << p.name;
}

INSTANTIATE_TEST_SUITE_P(ConformanceFiles, C3dRoundTrip,
                         ::testing::Values("c3d/sample01/Eb015pi.c3d", "c3d/sample01/Eb015pr.c3d",
                                           "c3d/sample01/Eb015vr.c3d", "c3d/sample01/Eb015si.c3d",
                                           "c3d/sample02/pc_real.c3d", "c3d/sample03/gait-pig-nz.c3d",
                                           "c3d/sample13/Dance.c3d", "c3d/sample16/basketball.c3d",
                                           "c3d/sample00_motion_analysis/Walk1.c3d",
                                           "c3d/btk_others/mocap36.c3d"));

TEST(C3dRoundTrip, BundledTakeIsBitExact)
{
  const Take original = readC3d(test::sampleTake());
  expectSameTake(original, reparse(original), true);
}

TEST(C3dRoundTrip, LabelsWithSpacesAndColons)
{
  Take take = readC3d(dataFile("c3d/sample01/Eb015pr.c3d"));
  take.setLabel(0, "Subject 1:L Heel");
  take.setLabel(1, "head:top:front");
  const Take back = reparse(take);
  EXPECT_EQ(back.label(0), "Subject 1:L Heel");
  EXPECT_EQ(back.label(1), "head:top:front");
}

TEST(C3dRoundTrip, MoreThan255MarkersUseLabels2)
{
  std::vector<std::string> labels;
  for (int i = 0; i < 300; ++i)
    labels.push_back("marker" + std::to_string(i));
  Take take(labels, 4, 120.0);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    take.setPosition(1, m, Eigen::Vector3d(static_cast<double>(m), 0.5, -2.25));
    take.valid()(1, m) = true;
    take.residuals()(1, m) = 0.0;
  }
  const std::string bytes = encodeC3d(take);
  const Take back = parseC3d(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "many.c3d");
  EXPECT_NE(back.parameters().find("POINT", "LABELS2"), nullptr);
  expectSameTake(take, back, true);
}

TEST(C3dRoundTrip, MoreThan65535FramesUseTrialFields)
{
  Take take({"a", "b"}, 70000, 240.0);
  take.setFirstFrame(5);
  for (Eigen::Index f = 0; f < take.frameCount(); f += 7) {
    take.setPosition(f, 1, Eigen::Vector3d(static_cast<double>(f), 1.0, 2.0));
    take.valid()(f, 1) = true;
    take.residuals()(f, 1) = 0.0;
  }
  const Take back = reparse(take);
  EXPECT_EQ(back.frameCount(), 70000);
  EXPECT_EQ(back.firstFrame(), 5);
  expectSameTake(take, back, true);
}

TEST(C3dRoundTrip, ThroughTrcKeepsSamplesGapsLabelsRateAndFirstFrame)
{
  // TRC holds marker positions only: the file's model outputs (Nexus angles) are left out.
  const Take read = readC3d(dataFile("c3d/sample03/gait-pig-nz.c3d"));
  ASSERT_LT(markerPoints(read).size(), static_cast<std::size_t>(read.markerCount())) << "the file has model outputs";
  const Take original = subsetTake(read, markerLabels(read));
  test::TempDir dir;
  writeTrc(read, dir.file("take.trc"));
  const Take viaTrc = readTrc(dir.file("take.trc"));
  const Take back = reparse(viaTrc);
  ASSERT_EQ(back.labels(), original.labels());
  EXPECT_EQ(back.frameCount(), original.frameCount());
  EXPECT_EQ(back.firstFrame(), original.firstFrame());
  EXPECT_NEAR(back.frameRate(), original.frameRate(), 1e-9);
  ASSERT_TRUE((back.valid() == original.valid()).all());
  for (Eigen::Index m = 0; m < original.markerCount(); ++m)
    for (Eigen::Index f = 0; f < original.frameCount(); ++f) {
      if (original.isValid(f, m)) {
        ASSERT_EQ(original.position(f, m), back.position(f, m)) << original.label(m) << " frame " << f;
      }
    }
}

TEST(C3dRoundTrip, UnitConversionRescalesResidualsAndKeepsThemExact)
{
  Take take = readC3d(dataFile("c3d/sample01/Eb015pi.c3d"));
  take.convertUnits(LengthUnit::Metre);
  const Take back = reparse(take);
  EXPECT_EQ(back.units(), LengthUnit::Metre);
  EXPECT_NEAR(back.trajectory(17)(16, 0), 0.285, 1e-7);
  EXPECT_LE((back.residuals() - take.residuals()).abs().maxCoeff(), 1e-9);
}

TEST(C3dWriter, WritesAtomicallyAndReportsUnwritablePaths)
{
  const Take take = readC3d(dataFile("c3d/sample02/pc_real.c3d"));
  test::TempDir dir;
  const auto target = dir.file("out.c3d");
  writeC3d(take, target);
  EXPECT_EQ(readC3d(target).frameCount(), take.frameCount());
  EXPECT_THROW(writeC3d(take, dir.file("missing/dir/out.c3d")), IoError);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path()))
    ++entries;
  EXPECT_EQ(entries, 1u) << "a temporary file was left behind";
}

} // namespace
} // namespace mocap
