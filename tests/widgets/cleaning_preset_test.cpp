// File ▸ Save Cleaning Preset…: the Cleaning dock's settings written as the preset `mocap batch
// --preset` reads (issue 17), so a take cleaned in the studio and an archive cleaned in a batch
// use the same options.
#include "../core/test_support.h"

#include "main_window.h"
#include "actions/cleaning_preset_actions.h"
#include "sample_window.h"
#include "panels/cleaning_panel.h"
#include "panels/gap_fill_step.h"
#include "document/take_document.h"

#include "mocap/base/file_io.h"
#include "mocap/batch/clean_preset.h"

#include <QAction>
#include <QCheckBox>
#include <QFileDialog>
#include <QSpinBox>
#include <QUndoStack>

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
  ASSERT_EQ(window->cleaningPresets()->save(path), QString());
  const CleanOptions preset = readCleanPreset(path.toStdString());
  ASSERT_TRUE(preset.fill && preset.spikes && preset.smooth);  // the dock's three pipeline steps
  EXPECT_TRUE(preset.fill->extrapolate);
  EXPECT_DOUBLE_EQ(preset.fill->minValidFraction, 0.35);
  EXPECT_DOUBLE_EQ(preset.fill->maxGapSeconds, 1.25);
  EXPECT_EQ(preset.fill->maxGap, 0);
  // What the studio writes is the canonical form: reading and writing it again changes nothing.
  EXPECT_EQ(readFileBytes(dir.file("studio.json")), cleanPresetJson(preset));
  // Head markers are the take's, not an option: only a tick puts them in (by label).
  EXPECT_TRUE(preset.stabilizeLabels.empty());
  ASSERT_EQ(window->cleaningPresets()->save(path, true), QString());
  EXPECT_EQ(readCleanPreset(path.toStdString()).stabilizeLabels, window->document().referenceLabels());

  EXPECT_NE(window->cleaningPresets()->save(QString::fromStdString((dir.file("missing") / "x.json").string())), QString());
  EXPECT_FALSE(std::filesystem::exists(dir.file("missing")));
}

TEST(CleaningPreset, SaveAsksBeforeTakingTheHeadMarkersAlong)
{
  const auto window = test::openSampleWindow(1280, 800);
  ASSERT_NE(window, nullptr);
  test::TempDir dir;
  const QString path = QString::fromStdString(dir.file("asked.json").string());
  bool offered = false, tickedByDefault = true;
  test::whenModal<QFileDialog>([&](QFileDialog* dialog) {
    auto* box = dialog->findChild<QCheckBox*>(QStringLiteral("includeHeadMarkers"));
    offered = box != nullptr && box->isEnabled();
    tickedByDefault = box == nullptr || box->isChecked();
    dialog->selectFile(path);
    static_cast<QDialog*>(dialog)->accept();  // QFileDialog::accept is protected; QDialog's is public
  });
  QAction* save = nullptr;
  for (QAction* action : window->findChildren<QAction*>())
    if (action->text() == QStringLiteral("Save &Cleaning Preset…"))
      save = action;
  ASSERT_NE(save, nullptr);
  save->trigger();
  EXPECT_TRUE(offered);
  EXPECT_FALSE(tickedByDefault);
  ASSERT_TRUE(std::filesystem::exists(dir.file("asked.json")));
  EXPECT_TRUE(readCleanPreset(path.toStdString()).stabilizeLabels.empty());
}

TEST(CleaningPreset, LoadSetsThePanelsOptionsAndLeavesTheTakeAlone)
{
  const auto window = test::openSampleWindow(1280, 800);
  ASSERT_NE(window, nullptr);
  ui::TakeDocument& document = window->document();
  const std::vector<std::string> reference = document.referenceLabels();
  const std::size_t steps = document.take().history().size();
  test::TempDir dir;
  writeFileAtomically(dir.file("p.json"),
                      R"({"stabilize": {"markers": ["elsewhere1", "elsewhere2", "elsewhere3"]},
                          "spikes": {"method": "off"},
                          "fill": {"method": "linear", "neighbours": 4, "max_gap_seconds": 1.5,
                                   "extrapolate": true, "min_valid_fraction": 0.4},
                          "smooth": {"method": "butterworth", "cutoff_hz": 9}})");
  CleanOptions wanted = readCleanPreset(dir.file("p.json"));
  ASSERT_EQ(window->cleaningPresets()->load(QString::fromStdString(dir.file("p.json").string())), QString());
  const CleanOptions shown = window->cleaningPanel()->cleanOptions();
  ASSERT_TRUE(shown.fill && shown.smooth);
  EXPECT_EQ(shown.fill->method, wanted.fill->method);
  EXPECT_EQ(shown.fill->neighbours, 4);
  EXPECT_DOUBLE_EQ(shown.fill->maxGapSeconds, 1.5);
  EXPECT_TRUE(shown.fill->extrapolate);
  EXPECT_DOUBLE_EQ(shown.fill->minValidFraction, 0.4);
  EXPECT_EQ(shown.smooth->method, wanted.smooth->method);
  EXPECT_DOUBLE_EQ(shown.smooth->cutoffHz, 9.0);
  EXPECT_TRUE(shown.stabilizeLabels.empty()) << "the preset's head markers are not this take's";
  // Nothing ran on the take: no edit, no history, the take's own head markers.
  EXPECT_EQ(document.undoStack()->count(), 0);
  EXPECT_FALSE(document.isModified());
  EXPECT_EQ(document.take().history().size(), steps);
  EXPECT_EQ(document.referenceLabels(), reference);
  // A file that is no preset is an error, and the panels keep what they show.
  writeFileAtomically(dir.file("bad.json"), R"({"fill": {"max_gap_s": 1}})");
  EXPECT_NE(window->cleaningPresets()->load(QString::fromStdString(dir.file("bad.json").string())), QString());
  EXPECT_DOUBLE_EQ(window->cleaningPanel()->cleanOptions().fill->maxGapSeconds, 1.5);
}

} // namespace
} // namespace mocap
