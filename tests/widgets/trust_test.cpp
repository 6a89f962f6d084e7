// What a technician must be able to trust in the studio: provenance survives save, reopen and
// crash recovery; nothing the reader warned about is hidden; the first run is usable; the wheel
// never changes a value it merely passes over.
#include "sample_files.h"
#include "../core/test_support.h"

#include "commands/apply_patches_command.h"
#include "commands/record_step_command.h"
#include "dialogs/manual_window.h"
#include "dialogs/read_warnings_dialog.h"
#include "document/autosave.h"
#include "document/face_mesh_model.h"
#include "document/take_document.h"
#include "main_window.h"
#include "sample_window.h"
#include "panels/cleaning_panel.h"
#include "panels/face_mesh_panel.h"
#include "panels/history_panel.h"
#include "views/face_mesh_scene.h"
#include "views/marker_view_3d.h"
#include "views/wheel_guard.h"

#include "mocap/io/c3d_writer.h"
#include "mocap/base/file_io.h"
#include "mocap/cleaning/fill/gap_fill.h"
#include "mocap/model/data_loss_record.h"
#include "mocap/model/provenance.h"
#include "mocap/io/take_io.h"
#include "checkout_paths.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QTest>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTimer>
#include <QToolButton>
#include <QTreeWidget>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <algorithm>

namespace mocap {
namespace {

using test::qpath;

using studio::MainWindow;
using ui::TakeDocument;

/// Fills the sample's gaps of up to 20 frames linearly as one command that records its step.
Eigen::Index fillShortGaps(TakeDocument& document)
{
  FillOptions options;
  options.method = FillMethod::Linear;
  options.maxGap = 20;
  FillResult result = fillGaps(document.take(), options);
  Eigen::Index samples = 0;
  std::vector<Eigen::Index> markers;
  for (const SamplePatch& p : result.patches) {
    samples += static_cast<Eigen::Index>(p.size());
    markers.push_back(p.marker);
  }
  auto* command = new QUndoCommand(QStringLiteral("Fill gaps"));
  new ui::ApplyPatchesCommand(document, std::move(result.patches), QString(), command);
  new ui::RecordStepCommand(
      document,
      ui::studioStep(document, "fill gaps", {{"method", "linear"}, {"max gap", "20 frames"}}, markers, 0, -1, samples),
      command);
  document.undoStack()->push(command);
  return samples;
}

Eigen::Index filledCount(const Take& take)
{
  Eigen::Index n = 0;
  for (const StateCounts& c : stateCounts(take))
    n += c.filled;
  return n;
}

class Trust : public ::testing::Test
{
protected:
  void SetUp() override { QSettings().clear(); }

  std::unique_ptr<MainWindow> showWindow()
  {
    auto window = std::make_unique<MainWindow>();
    window->show();
    EXPECT_TRUE(QTest::qWaitForWindowExposed(window.get()));
    return window;
  }
};

TEST_F(Trust, FilledSamplesAndHistorySurviveSaveAndReopen)
{
  test::TempDir dir;
  auto window = showWindow();
  ASSERT_EQ(window->openFile(qpath(test::sampleTake()), true), QString());
  const Eigen::Index samples = fillShortGaps(window->document());
  ASSERT_GT(samples, 0);
  ASSERT_EQ(window->document().save(qpath(dir.file("cleaned.c3d"))), QString());

  auto reopened = showWindow();
  ASSERT_EQ(reopened->openFile(qpath(dir.file("cleaned.c3d")), true), QString());
  EXPECT_EQ(filledCount(reopened->document().take()), samples);
  auto* history = reopened->findChild<ui::HistoryPanel*>();
  ASSERT_NE(history, nullptr);
  ASSERT_EQ(history->steps()->topLevelItemCount(), 1);
  const QTreeWidgetItem* step = history->steps()->topLevelItem(0);
  EXPECT_EQ(step->text(0), QStringLiteral("fill gaps"));
  EXPECT_TRUE(step->text(1).contains(QStringLiteral("linear"))) << step->text(1).toStdString();
  EXPECT_EQ(step->text(4), QString::number(samples));

  // Undo takes the step out of the history with the samples; redo puts both back.
  window->document().undoStack()->undo();
  EXPECT_TRUE(window->document().take().history().empty());
  EXPECT_EQ(filledCount(window->document().take()), 0);
  window->document().undoStack()->redo();
  EXPECT_EQ(window->document().take().history().size(), 1u);
}

TEST_F(Trust, RecoveryKeepsStatesHistoryLayoutAndFaceMesh)
{
  test::TempDir dir;
  TakeDocument document;
  ASSERT_EQ(document.open(qpath(test::sampleTake())), QString());
  ui::Autosave autosave(document, qpath(dir.path()));
  ui::SessionState session;
  session.meshPath = QStringLiteral("/somewhere/face.obj");
  autosave.setStateProvider([&session] { return session; });
  const Eigen::Index samples = fillShortGaps(document);
  autosave.saveInBackground();  // the timer's path: written on a worker thread
  autosave.waitForWrite();
  QCoreApplication::processEvents();
  ASSERT_TRUE(QFile::exists(autosave.recoveryPath()));
  const Take recovered = readTake(autosave.recoveryPath().toStdString());
  EXPECT_EQ(filledCount(recovered), samples);
  EXPECT_EQ(recovered.history(), document.take().history());

  const QString dead = qpath(dir.file("take-2147480001.c3d"));
  ASSERT_TRUE(QFile::copy(autosave.recoveryPath(), dead));
  ASSERT_TRUE(QFile::copy(autosave.recoveryPath() + ".ini", dead + ".ini"));
  ASSERT_TRUE(QFile::copy(autosave.recoveryPath() + ".session", dead + ".session"));
  const auto leftovers = ui::Autosave::leftovers(qpath(dir.path()));
  ASSERT_EQ(leftovers.size(), 1u);
  const std::optional<ui::SessionState> kept = ui::Autosave::readState(leftovers.front());
  ASSERT_TRUE(kept.has_value());
  EXPECT_EQ(kept->meshPath, QStringLiteral("/somewhere/face.obj"));
  ui::Autosave::remove(leftovers.front());
  EXPECT_FALSE(QFile::exists(dead + ".session")) << "the state goes with its take";
}

TEST_F(Trust, TheStudioRecoversTheFaceMeshAndBinding)
{
  const QString folder = ui::Autosave::defaultFolder();
  QDir(folder).removeRecursively();
  {
    auto window = showWindow();
    ASSERT_EQ(window->openFile(qpath(test::sampleTake()), true), QString());
    ASSERT_EQ(window->loadFaceMesh(QString::fromUtf8(checkout::sampleDir()) + QStringLiteral("/canonical_face_model.obj"),
                                   QString::fromUtf8(checkout::sampleDir()) + QStringLiteral("/Facial-Sing.binding.json")),
              QString());
    fillShortGaps(window->document());
    ASSERT_EQ(window->autosave()->saveNow(), QString());
    // A crash: the recovery file stays as if another (dead) process had left it.
    const QString dead = folder + QStringLiteral("/take-2147480002.c3d");
    ASSERT_TRUE(QFile::copy(window->autosave()->recoveryPath(), dead));
    ASSERT_TRUE(QFile::copy(window->autosave()->recoveryPath() + ".ini", dead + ".ini"));
    ASSERT_TRUE(QFile::copy(window->autosave()->recoveryPath() + ".session", dead + ".session"));
    window->document().undoStack()->setClean();  // close without asking
  }
  auto window = showWindow();
  QTimer::singleShot(0, [] {
    if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
      box->button(QMessageBox::Yes)->click();
  });
  ASSERT_TRUE(window->offerRecovery());
  EXPECT_GT(filledCount(window->document().take()), 0);
  EXPECT_EQ(window->document().take().history().size(), 1u);
  EXPECT_TRUE(window->faceMeshPanel()->model().hasMesh());
  EXPECT_GT(window->faceMeshPanel()->model().binding().markers.size(), 0u);
  QDir(folder).removeRecursively();
}

TEST_F(Trust, ATruncatedTakeMustBeAcknowledgedAndSaysIncomplete)
{
  test::TempDir dir;
  const std::string bytes = readFileBytes(test::sampleTake());
  writeFileAtomically(dir.file("cut.c3d"), std::string_view(bytes).substr(0, bytes.size() / 20));
  auto window = showWindow();
  QStringList listed;
  QString title;
  test::whenModal<ui::ReadWarningsDialog>([&](ui::ReadWarningsDialog* dialog) {  // inside its exec()
    title = dialog->windowTitle();
    for (int i = 0; i < dialog->list()->count(); ++i)
      listed << dialog->list()->item(i)->text();
    dialog->accept();
  });
  ASSERT_EQ(window->openFile(qpath(dir.file("cut.c3d"))), QString());
  ASSERT_FALSE(listed.isEmpty()) << "no dialog to acknowledge";
  EXPECT_TRUE(title.contains(QStringLiteral("incomplete"))) << title.toStdString();
  EXPECT_TRUE(listed.front().contains(QStringLiteral("truncated"))) << listed.front().toStdString();
  // Every warning is listed, not only the first.
  EXPECT_EQ(listed.size(), static_cast<int>(window->document().loadWarnings().size()));
  EXPECT_TRUE(window->windowTitle().contains(QStringLiteral("(incomplete)"))) << window->windowTitle().toStdString();
  auto* button = window->findChild<QToolButton*>(QStringLiteral("readWarningsButton"));
  ASSERT_NE(button, nullptr);
  EXPECT_TRUE(button->isVisible());

  // A whole take afterwards is not called incomplete.
  ASSERT_EQ(window->openFile(qpath(test::sampleTake()), true), QString());
  EXPECT_FALSE(window->windowTitle().contains(QStringLiteral("(incomplete)")));
}

TEST_F(Trust, WrappedCoordinatesAreCalledWrongNotMissingAndCanBeAcknowledged)
{
  // The ART file's head marker wrapped round past the 16-bit range: every sample is in the take,
  // some are wrong. The dialog said "Data is missing from …" and the title "(incomplete)".
  auto window = showWindow();
  QString title, heading;
  bool offered = false;
  test::whenModal<ui::ReadWarningsDialog>([&](ui::ReadWarningsDialog* dialog) {
    title = dialog->windowTitle();
    heading = dialog->heading();
    offered = dialog->acknowledgeButton() != nullptr;
    if (offered)
      dialog->acknowledgeButton()->click();
    else
      dialog->accept();
  });
  const QString path = qpath(test::dataFile("c3d/sample37/ART-Human_tools_integer_6dofLimbs.c3d"));
  ASSERT_EQ(window->openFile(path), QString());
  EXPECT_TRUE(title.contains(QStringLiteral("wrong data"))) << title.toStdString();
  EXPECT_FALSE(title.contains(QStringLiteral("incomplete"))) << title.toStdString();
  EXPECT_TRUE(heading.contains(QStringLiteral("is wrong"))) << heading.toStdString();
  EXPECT_FALSE(heading.contains(QStringLiteral("missing"))) << heading.toStdString();
  EXPECT_TRUE(window->windowTitle().contains(QStringLiteral("(wrong data)"))) << window->windowTitle().toStdString();
  auto* button = window->findChild<QToolButton*>(QStringLiteral("readWarningsButton"));
  ASSERT_NE(button, nullptr);
  EXPECT_TRUE(button->text().contains(QStringLiteral("Wrong data"))) << button->text().toStdString();

  // Acknowledged in the dialog: one undoable step; a saved copy then lists it without raising it.
  ASSERT_TRUE(offered);
  TakeDocument& document = window->document();
  const auto acknowledged = [&] {
    const std::vector<DataLossRecord> records = dataLossRecords(document.take());
    return !records.empty() && std::all_of(records.begin(), records.end(),
                                           [](const DataLossRecord& r) { return r.acknowledged; });
  };
  EXPECT_TRUE(acknowledged());
  document.undoStack()->undo();
  EXPECT_FALSE(acknowledged()) << "undone";
  document.undoStack()->redo();
  EXPECT_TRUE(acknowledged()) << "redone";
  test::TempDir dir;
  ASSERT_EQ(document.save(qpath(dir.file("acknowledged.trc")), true), QString());
  std::vector<std::string> warnings, dataLoss;
  const Take saved = readTake(dir.file("acknowledged.trc"), &warnings, &dataLoss);
  EXPECT_TRUE(dataLoss.empty()) << dataLoss.front();
  ASSERT_EQ(dataLossRecords(saved).size(), 1u);
  EXPECT_TRUE(dataLossRecords(saved).front().acknowledged);
}

TEST_F(Trust, FirstRunFillsMostOfTheScreenWithTheViewAtLeastHalf)
{
  auto window = showWindow();
  QTest::qWait(50);
  const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
  EXPECT_GE(window->width(), screen.width() * 8 / 10);
  EXPECT_GE(window->height(), screen.height() * 8 / 10);
  QString docks;
  for (const QDockWidget* dock : window->findChildren<QDockWidget*>())
    if (dock->isVisible())
      docks += QStringLiteral("%1 %2 (min %3); ").arg(dock->objectName()).arg(dock->width()).arg(dock->minimumSizeHint().width());
  // On failure, say which widgets keep the dock wide.
  for (const QWidget* w : window->cleaningPanel()->findChildren<QWidget*>())
    if (w->minimumSizeHint().width() > 300)
      docks += QStringLiteral("\n%1 %2 %3").arg(QString::fromLatin1(w->metaObject()->className()), w->objectName()).arg(w->minimumSizeHint().width());
  EXPECT_GE(window->markerView()->width(), window->width() / 2) << docks.toStdString();
}

TEST_F(Trust, TheWindowFitsA1280By800ScreenWithEveryPanelShown)
{
  auto window = showWindow();
  // A laptop's 1280×800 less a panel bar: the window's smallest size must fit, with any dock open
  // (a dock's minimum adds to the window's, so a tall panel pushed the status bar off screen).
  const QSize screen(1280, 760);
  QString tooBig;
  for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
    dock->show();
    QTest::qWait(10);
    const QSize minimum = window->minimumSizeHint().expandedTo(window->minimumSize());
    if (minimum.width() > screen.width() || minimum.height() > screen.height())
      tooBig += QStringLiteral("%1: window at least %2×%3; ")
                    .arg(dock->objectName())
                    .arg(minimum.width())
                    .arg(minimum.height());
  }
  EXPECT_TRUE(tooBig.isEmpty()) << tooBig.toStdString();
}

TEST_F(Trust, HelpManualShowsTheBundledManualWithItsPictures)
{
  auto window = showWindow();
  QAction* manualAction = nullptr;
  for (QAction* action : window->findChildren<QAction*>())
    if (action->shortcut() == QKeySequence(QKeySequence::HelpContents))
      manualAction = action;
  ASSERT_NE(manualAction, nullptr) << "Help ▸ Manual has F1";
  manualAction->trigger();
  auto* manual = window->findChild<ui::ManualWindow*>();
  ASSERT_NE(manual, nullptr);
  EXPECT_TRUE(manual->isVisible());
  const QStringList headings = manual->headings();
  EXPECT_TRUE(headings.contains(QStringLiteral("The studio"))) << headings.join(QLatin1Char('|')).toStdString();
  EXPECT_TRUE(headings.contains(QStringLiteral("The mocap command line"))) << headings.join(QLatin1Char('|')).toStdString();
  EXPECT_FALSE(headings.contains(QStringLiteral("The two commands"))) << "the manual is for users, not builders";
  // The pictures are bundled too: the screenshot resolves from the text's own reference.
  const QVariant picture =
      manual->browser()->document()->resource(QTextDocument::ImageResource, QUrl(QStringLiteral("docs/images/studio.png")));
  EXPECT_TRUE(picture.isValid() && !picture.value<QImage>().isNull()) << "docs/images/studio.png not bundled";
  const int before = manual->browser()->verticalScrollBar()->value();
  manual->showHeading(static_cast<int>(headings.indexOf(QStringLiteral("The mocap command line"))));
  EXPECT_GT(manual->browser()->verticalScrollBar()->value(), before) << "choosing a heading scrolls to it";
}

TEST_F(Trust, SaveAsHasCtrlShiftS)
{
  auto window = showWindow();
  bool found = false;
  for (const QAction* action : window->findChildren<QAction*>())
    found = found || action->shortcut() == QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S);
  EXPECT_TRUE(found);
}

TEST_F(Trust, TheWheelScrollsADockInsteadOfChangingAComboItPassesOver)
{
  ui::WheelGuard::install();
  QScrollArea area;
  auto* content = new QWidget;
  auto* layout = new QVBoxLayout(content);
  auto* combo = new QComboBox;
  combo->addItems({QStringLiteral("a"), QStringLiteral("b"), QStringLiteral("c")});
  layout->addWidget(combo);
  layout->addSpacing(2000);
  area.setWidget(content);
  area.resize(200, 200);
  area.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&area));
  const QPoint at = combo->rect().center();
  QWheelEvent wheel(QPointF(at), QPointF(combo->mapToGlobal(at)), QPoint(), QPoint(0, -120), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(combo, &wheel);
  EXPECT_EQ(combo->currentIndex(), 0) << "the combo changed under a passing wheel";
  EXPECT_GT(area.verticalScrollBar()->value(), 0) << "the dock did not scroll";
  // With the focus, the wheel is the combo's.
  area.activateWindow();
  if (!QTest::qWaitForWindowActive(&area))
    GTEST_SKIP() << "no active window under this display";
  combo->setFocus();
  QWheelEvent focused(QPointF(at), QPointF(combo->mapToGlobal(at)), QPoint(), QPoint(0, -120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(combo, &focused);
  EXPECT_EQ(combo->currentIndex(), 1);
}

} // namespace
} // namespace mocap
