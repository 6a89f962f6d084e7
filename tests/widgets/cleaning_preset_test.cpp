// File ▸ Save Cleaning Preset…: the Cleaning dock's settings written as the preset `mocap batch
// --preset` reads (issue 17), so a take cleaned in the studio and an archive cleaned in a batch
// use the same options.
#include "../core/test_support.h"

#include "main_window.h"
#include "sample_window.h"
#include "panels/cleaning_panel.h"
#include "panels/gap_fill_step.h"

#include "mocap/base/file_io.h"
#include "mocap/batch/clean_preset.h"

#include <QCheckBox>
#include <QSpinBox>

#include <gtest/gtest.h>

namespace mocap {
namespace {

TEST(CleaningPreset, TheStudioSavesItsCleaningSettingsAsThePresetTheBatchReads)
{
  const auto window = test::openSampleWindow(1280, 800);
  ASSERT_NE(window, nullptr);
  auto* fill = window->cleaningPanel()->step<ui::GapFillStep>();
  ASSERT_NE(fill, nullptr);
  auto* extrapolate = fill->findChild<QCheckBox*>(QStringLiteral("extrapolate"));
  auto* minValid = fill->findChild<QSpinBox*>(QStringLiteral("minValid"));
  ASSERT_TRUE(extrapolate && minValid);
  extrapolate->setChecked(true);
  minValid->setValue(35);
  fill->setMaxGapSeconds(1.25);

  test::TempDir dir;
  const QString path = QString::fromStdString(dir.file("studio.json").string());
  ASSERT_EQ(window->saveCleaningPreset(path), QString());
  const CleanOptions preset = readCleanPreset(path.toStdString());
  ASSERT_TRUE(preset.fill && preset.spikes && preset.smooth);  // the dock's three pipeline steps
  EXPECT_TRUE(preset.fill->extrapolate);
  EXPECT_DOUBLE_EQ(preset.fill->minValidFraction, 0.35);
  EXPECT_DOUBLE_EQ(preset.fill->maxGapSeconds, 1.25);
  EXPECT_EQ(preset.fill->maxGap, 0);
  // What the studio writes is the canonical form: reading and writing it again changes nothing.
  EXPECT_EQ(readFileBytes(dir.file("studio.json")), cleanPresetJson(preset));
  // The sample's reference markers (root-1…) go in by label.
  EXPECT_FALSE(preset.stabilizeLabels.empty());

  EXPECT_NE(window->saveCleaningPreset(QString::fromStdString((dir.file("missing") / "x.json").string())), QString());
  EXPECT_FALSE(std::filesystem::exists(dir.file("missing")));
}

} // namespace
} // namespace mocap
