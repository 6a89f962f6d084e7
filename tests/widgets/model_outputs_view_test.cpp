// Model outputs in the studio (issue 30): a Nexus-style file's joint angles, forces, moments and
// powers are not drawn or gap-listed until View ▸ Show Model Outputs is on, and the status bar
// says so.
#include "../core/test_support.h"
#include "foreign_takes.h"

#include "document/take_document.h"
#include "main_window.h"
#include "models/gap_table_model.h"
#include "panels/gap_list_panel.h"
#include "sample_window.h"
#include "views/marker_view_3d.h"

#include "mocap/io/take_io.h"

#include <QAction>
#include <QLabel>
#include <QSettings>

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace mocap {
namespace {

TEST(ModelOutputsView, HiddenAndUnlistedUntilShown)
{
  test::TempDir dir;
  writeTake(test::nexusCleaningTake(), dir.file("nexus.c3d"));
  const auto window = test::openSampleWindow(1280, 800);
  ASSERT_NE(window, nullptr);
  ASSERT_EQ(window->openFile(QString::fromStdString(dir.file("nexus.c3d").string()), true), QString());
  const Take& take = window->document().take();
  const Eigen::Index angles = *take.markerIndex("LHipAngles");
  const Eigen::Index lasi = *take.markerIndex("LASI");
  const ui::GapTableModel* gaps = window->gapListPanel()->model();
  const auto gapLabels = [&] {
    std::set<std::string> labels;
    for (int row = 0; row < gaps->rowCount(); ++row)
      labels.insert(take.label(gaps->gapAt(row).marker));
    return labels;
  };
  const ui::MarkerView3d& view = *window->markerView();
  auto* note = window->findChild<QLabel*>(QStringLiteral("modelOutputsNote"));
  auto* show = window->findChild<QAction*>(QStringLiteral("showModelOutputsAction"));
  ASSERT_NE(note, nullptr);
  ASSERT_NE(show, nullptr);

  EXPECT_FALSE(show->isChecked()) << "off by default";
  EXPECT_EQ(gapLabels(), (std::set<std::string>{"LASI", "RASI", "LPSI", "RPSI"}));
  EXPECT_TRUE(view.markerColor(lasi).has_value());
  EXPECT_FALSE(view.markerColor(angles).has_value()) << "a joint angle drawn as a marker";
  EXPECT_TRUE(note->isVisible());
  EXPECT_EQ(note->text(), QStringLiteral("5 model outputs hidden"));
  EXPECT_TRUE(note->toolTip().contains(QStringLiteral("5 model outputs (2 angles, 1 force, 1 moment, 1 power) hidden")))
      << note->toolTip().toStdString();

  show->trigger();
  EXPECT_EQ(gapLabels().size(), 9u);
  EXPECT_TRUE(view.markerColor(angles).has_value());
  EXPECT_TRUE(note->text().contains(QStringLiteral("shown"))) << note->text().toStdString();
  EXPECT_TRUE(QSettings().value(QStringLiteral("view/modelOutputs")).toBool()) << "remembered";

  show->trigger();
  EXPECT_EQ(gapLabels().size(), 4u);
  EXPECT_FALSE(view.markerColor(angles).has_value());

  // The sample take has no model outputs: no note.
  ASSERT_EQ(window->openFile(QString::fromStdString(test::sampleTake().string()), true), QString());
  EXPECT_FALSE(note->isVisible());
}

} // namespace
} // namespace mocap
