// The session's view state and typed options, and the actions moved out of the main window
// (issue 31), without a window: options read once, clamped, remembered and announced; the view
// state follows them and the 3D view follows the view state; the reference-marker and
// cleaning-preset actions push or write what they should.
#include "../core/test_support.h"
#include "language.h"

#include "actions/cleaning_preset_actions.h"
#include "actions/head_stabilized_view_action.h"
#include "actions/option_toggle.h"
#include "actions/reference_marker_actions.h"
#include "actions/take_file_actions.h"
#include "document/remembered_folder.h"
#include "document/session_option.h"
#include "document/studio_options.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "document/view_state.h"
#include "panels/layout_planning_panel.h"
#include "views/blendshape_scene.h"
#include "views/face_mesh_scene.h"
#include "views/marker_view_3d.h"
#include "views/mesh_layer.h"
#include "views/scene_settings.h"
#include "views/sample_colors.h"
#include "views/session_scene.h"

#include "mocap/base/file_io.h"
#include "mocap/io/take_io.h"

#include <QAction>
#include <QCoreApplication>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>
#include <QSignalSpy>
#include <QUndoStack>
#include <QWidget>

#include <gtest/gtest.h>

#include <limits>

namespace mocap {
namespace {

QString optionsTestPath(const std::filesystem::path& path)
{
  return QString::fromStdString(path.string());
}

/// A three-frame take with markers a, b, c, d opened in `session`.
void openOptionsTestTake(ui::StudioSession& session, const std::filesystem::path& path)
{
  writeTake(Take({"a", "b", "c", "d"}, 3, 100.0), path.string());
  session.document().open(ui::TakeDocument::read(optionsTestPath(path)), optionsTestPath(path));
}

TEST(SessionOptions, AreReadClampedRememberedAndAnnouncedOnlyOnAChange)
{
  QSettings().clear();
  QSettings settings;
  settings.setValue(QStringLiteral("view/trailFrames"), -7);
  settings.setValue(QStringLiteral("view/markerSizePercent"), std::numeric_limits<double>::quiet_NaN());
  settings.setValue(QStringLiteral("view/colors/edited"), QStringLiteral("not-a-colour"));
  settings.sync();
  {
    ui::StudioOptions options;
    EXPECT_EQ(options.trailFrames.get(), 0) << "clamped into its range";
    EXPECT_DOUBLE_EQ(options.markerSizePercent.get(), ui::Preferences{}.markerSizePercent);
    EXPECT_EQ(options.colors.get().edited, ui::ColorScheme{}.edited);
    EXPECT_FALSE(options.keepRig.get());

    QObject follower;
    std::vector<int> seen;
    options.trailFrames.follow(&follower, [&seen](int frames) { seen.push_back(frames); });
    EXPECT_EQ(seen, std::vector<int>{0}) << "a follower gets the value at once";
    EXPECT_TRUE(options.trailFrames.set(120));
    EXPECT_FALSE(options.trailFrames.set(120)) << "the same value is no change";
    options.trailFrames = 100000;  // clamped
    EXPECT_EQ(seen, (std::vector<int>{0, 120, 1000}));
    EXPECT_EQ(QSettings().value(QStringLiteral("view/trailFrames")).toInt(), 1000) << "remembered";
    options.keepRig = true;
    ui::ColorScheme colors;
    colors.filled = QColor(1, 2, 3);
    options.colors = colors;
  }
  const ui::StudioOptions again;
  EXPECT_EQ(again.trailFrames.get(), 1000);
  EXPECT_TRUE(again.keepRig.get());
  EXPECT_EQ(again.colors.get().filled, QColor(1, 2, 3));
  EXPECT_EQ(QSettings().value(QStringLiteral("view/colors/filled")).toString(), QStringLiteral("#010203"));
  EXPECT_EQ(ui::Preferences::load().trailFrames, 1000) << "the preferences are the options' value";
  QSettings().clear();
}

TEST(SessionOptions, AToggleActionShowsAndSetsItsOption)
{
  QSettings().clear();
  ui::StudioOptions options;
  QMenu menu;
  QAction* toggle = ui::addOptionToggle(menu, QStringLiteral("Links"), options.linksVisible);
  EXPECT_TRUE(toggle->isCheckable());
  EXPECT_FALSE(toggle->isChecked());
  options.linksVisible = true;
  EXPECT_TRUE(toggle->isChecked()) << "the action follows the option";
  toggle->setChecked(false);
  EXPECT_FALSE(options.linksVisible.get()) << "and sets it";
  EXPECT_FALSE(QSettings().value(QStringLiteral("view/links")).toBool());
  QSettings().clear();
}

TEST(SessionViewState, FollowsTheOptionsAndTheSessionFollowsItsOwn)
{
  QSettings().clear();
  ui::StudioSession session;
  ui::ViewState& view = session.view();
  QSignalSpy trails(&view, &ui::ViewState::trailFramesChanged);
  QSignalSpy axis(&view, &ui::ViewState::upAxisChanged);
  session.followOptions();
  EXPECT_EQ(trails.count(), 0) << "the defaults are no change";
  ui::StudioOptions& options = session.options();
  options.trailFrames = 12;
  options.markerSizePercent = 2.0;
  options.displayUnit = QStringLiteral("cm");
  options.followHead = true;
  options.linksVisible = true;
  EXPECT_EQ(view.trailFrames(), 12);
  EXPECT_EQ(trails.count(), 1);
  EXPECT_DOUBLE_EQ(view.markerScale(), 0.02);
  EXPECT_EQ(view.displayUnit(), LengthUnit::Centimetre);
  EXPECT_TRUE(view.followHead());
  EXPECT_TRUE(view.linksVisible());
  options.upAxis = 1;
  options.upAxis = 7;  // not an axis: Z
  EXPECT_EQ(axis.count(), 2);
  EXPECT_EQ(view.upAxis(), 2);

  QSignalSpy colors(&view, &ui::ViewState::colorsChanged);
  ui::ColorScheme scheme;
  scheme.flagged = QColor(9, 9, 9);
  options.colors = scheme;
  EXPECT_EQ(colors.count(), 1);
  EXPECT_EQ(ui::colorScheme().flagged, QColor(9, 9, 9)) << "the scheme the views draw with";
  options.colors = ui::ColorScheme{};
  EXPECT_EQ(ui::colorScheme().flagged, ui::ColorScheme{}.flagged);

  options.keepRig = true;
  EXPECT_TRUE(session.keepRig());
  options.showModelOutputs = true;
  EXPECT_TRUE(session.document().showsModelOutputs());
  QSettings().clear();
}

TEST(SessionViewState, DrivesTheMarkerViewThatObservesIt)
{
  QSettings().clear();
  test::TempDir dir;
  ui::StudioSession session;
  openOptionsTestTake(session, dir.file("take.c3d"));
  ui::MarkerView3d view(session.document());
  view.observe(session.view());
  ui::ViewState& state = session.view();
  state.setTrailFrames(7);
  state.setMarkerScale(0.03);
  state.setUpAxis(1);
  state.setLinksVisible(true);
  state.setFollowHead(true);
  state.setLayoutHighlight({true, false, true, false}, {});
  EXPECT_EQ(view.trailFrames(), 7);
  EXPECT_DOUBLE_EQ(view.markerScale(), 0.03);
  EXPECT_EQ(view.upAxis(), 1);
  EXPECT_TRUE(view.linksVisible()) << "a take with no valid sample has nothing to link, and no error";
  EXPECT_TRUE(view.links().empty());
  EXPECT_TRUE(view.followHead());
  EXPECT_EQ(view.layoutHighlight(), (std::vector<bool>{true, false, true, false}));
  state.setLayoutHighlight({}, {});
  EXPECT_TRUE(view.layoutHighlight().empty()) << "the highlight goes with the state's";
}

TEST(SessionReferenceMarkerActions, PushOneUndoableEditOnlyWhenTheSetChanges)
{
  test::TempDir dir;
  ui::StudioSession session;
  openOptionsTestTake(session, dir.file("take.c3d"));
  ui::TakeDocument& document = session.document();
  QWidget parent;
  ui::ReferenceMarkerActions actions(document, parent);
  QSignalSpy messages(&actions, &ui::ReferenceMarkerActions::message);
  const int before = document.undoStack()->count();
  EXPECT_TRUE(actions.change({2, 0, 2, 1}));
  EXPECT_EQ(document.referenceMarkers(), (std::vector<Eigen::Index>{0, 1, 2})) << "sorted, repeats dropped";
  EXPECT_EQ(document.undoStack()->count(), before + 1);
  EXPECT_FALSE(actions.change({1, 2, 0})) << "the same set pushes nothing";
  EXPECT_EQ(document.undoStack()->count(), before + 1);

  document.setSelection({0, 3});
  actions.setSelected();
  EXPECT_EQ(messages.count(), 1) << "fewer than three: why nothing happened";
  document.setSelection({1, 2, 3});
  actions.setSelected();
  EXPECT_EQ(document.referenceMarkers(), (std::vector<Eigen::Index>{1, 2, 3}));
  actions.acceptProposed({0, 1, 3});
  EXPECT_EQ(document.referenceMarkers(), (std::vector<Eigen::Index>{0, 1, 3}));
  EXPECT_EQ(messages.count(), 2) << "accepting says how to take it back";
  document.undoStack()->undo();
  EXPECT_EQ(document.referenceMarkers(), (std::vector<Eigen::Index>{1, 2, 3}));
}

TEST(SessionCleaningPresetActions, WriteAndReadThePresetThroughTheirSource)
{
  test::TempDir dir;
  ui::StudioSession session;
  openOptionsTestTake(session, dir.file("take.c3d"));
  (void)session.document().setReferenceMarkers({0, 1, 2});
  CleanOptions shown;
  shown.fill.reset();
  std::vector<CleanOptions> loadedOptions;
  QWidget parent;
  ui::CleaningPresetActions actions(session.document(), parent,
                                    {[&shown] { return shown; },
                                     [&loadedOptions](const CleanOptions& options) {
                                       loadedOptions.push_back(options);
                                       return QStringList{QStringLiteral("Gap fill")};
                                     }});
  QSignalSpy loaded(&actions, &ui::CleaningPresetActions::loaded);
  QSignalSpy messages(&actions, &ui::CleaningPresetActions::message);

  const QString plain = optionsTestPath(dir.file("plain.json"));
  ASSERT_EQ(actions.save(plain), QString());
  EXPECT_TRUE(readCleanPreset(plain.toStdString()).stabilizeLabels.empty()) << "a preset carries options only";
  EXPECT_FALSE(readCleanPreset(plain.toStdString()).fill.has_value());
  const QString withHead = optionsTestPath(dir.file("head.json"));
  ASSERT_EQ(actions.save(withHead, true), QString());
  EXPECT_EQ(readCleanPreset(withHead.toStdString()).stabilizeLabels, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_NE(actions.save(optionsTestPath(dir.file("missing") / "x.json")), QString());

  ASSERT_EQ(actions.load(withHead), QString());
  ASSERT_EQ(loadedOptions.size(), 1U);
  EXPECT_FALSE(loadedOptions.front().fill.has_value());
  EXPECT_EQ(loaded.count(), 1);
  ASSERT_EQ(messages.count(), 1);
  const QString said = messages.front().front().toString();
  EXPECT_TRUE(said.contains(QStringLiteral("Gap fill"))) << said.toStdString();
  EXPECT_TRUE(said.contains(QStringLiteral("a, b, c"))) << "its head markers are not the take's";

  writeFileAtomically(dir.file("bad.json").string(), "{ not json");
  EXPECT_NE(actions.load(optionsTestPath(dir.file("bad.json"))), QString());
  EXPECT_EQ(loadedOptions.size(), 1U) << "a bad preset loads nothing";
  EXPECT_EQ(loaded.count(), 1);
}

TEST(SessionTakeFileActions, OpenRemembersTheFilesNewestFirstAndAFailedOpenKeepsTheTake)
{
  QSettings().clear();
  test::TempDir dir;
  for (const char* name : {"one.c3d", "two.c3d"})
    writeTake(Take({"a", "b"}, 3, 100.0), dir.file(name).string());
  const QString one = QFileInfo(optionsTestPath(dir.file("one.c3d"))).absoluteFilePath();
  const QString two = QFileInfo(optionsTestPath(dir.file("two.c3d"))).absoluteFilePath();
  ui::StudioSession session;
  QWidget parent;
  ui::TakeFileActions files(session.document(), session.options(), parent);
  QSignalSpy opened(&files, &ui::TakeFileActions::opened);
  QMenu recent;
  files.followRecentFiles(recent);
  EXPECT_FALSE(recent.isEnabled()) << "nothing opened yet";
  ASSERT_EQ(files.open(one, true), QString());
  ASSERT_EQ(files.open(two, true), QString());
  ASSERT_EQ(files.open(one, true), QString());
  EXPECT_EQ(opened.count(), 3);
  EXPECT_EQ(session.options().recentFiles.get(), (QStringList{one, two})) << "newest first, once each";
  EXPECT_EQ(QSettings().value(QStringLiteral("recentFiles")).toStringList(), (QStringList{one, two}));
  EXPECT_EQ(session.options().lastFolder.get(), QFileInfo(one).absolutePath());
  ASSERT_EQ(recent.actions().size(), 2);
  EXPECT_EQ(recent.actions().front()->toolTip(), one);

  EXPECT_NE(files.open(optionsTestPath(dir.file("missing.c3d")), true), QString());
  EXPECT_EQ(session.document().filePath(), one) << "a failed open keeps the open take";
  EXPECT_EQ(opened.count(), 3);
  EXPECT_EQ(session.options().recentFiles.get().size(), 2);
  QSettings().clear();
}

TEST(SessionOptions, ForgetRemovesTheKeyAndAnnouncesTheDefault)
{
  QSettings().clear();
  ui::SessionOption<QString> actor(QStringLiteral("actorForTake/x"), QStringLiteral("none"));
  actor = QStringLiteral("/actors/a.json");
  ASSERT_TRUE(QSettings().contains(QStringLiteral("actorForTake/x")));
  QObject follower;
  std::vector<QString> seen;
  actor.follow(&follower, [&seen](const QString& path) { seen.push_back(path); });
  actor.forget();
  EXPECT_FALSE(QSettings().contains(QStringLiteral("actorForTake/x"))) << "the key is gone";
  EXPECT_EQ(actor.get(), QStringLiteral("none"));
  EXPECT_EQ(seen, (std::vector<QString>{QStringLiteral("/actors/a.json"), QStringLiteral("none")}));
  actor.forget();
  EXPECT_EQ(seen.size(), 2U) << "forgetting the default is no change";
  QSettings().clear();
}

TEST(SessionOptions, AFolderIsRememberedUnderItsGroupsKeyOfBefore)
{
  QSettings().clear();
  EXPECT_EQ(ui::rememberedFolder(QStringLiteral("export/")), QString()) << "none yet: the caller's fallback";
  QSettings().setValue(QStringLiteral("actor/folder"), QStringLiteral("/saved/by/the/last/version"));
  EXPECT_EQ(ui::rememberedFolder(QStringLiteral("actor/")), QStringLiteral("/saved/by/the/last/version"));
  ui::rememberFolder(QStringLiteral("export/"), QStringLiteral("/takes/out/take.fbx"));
  EXPECT_EQ(QSettings().value(QStringLiteral("export/folder")).toString(), QStringLiteral("/takes/out"));
  EXPECT_EQ(ui::rememberedFolder(QStringLiteral("export/")), QStringLiteral("/takes/out"));
  QSettings().clear();
}

TEST(SessionOptions, APanelLoadsTheSettingsTheLastVersionSaved)
{
  // Written under the keys the panel wrote by hand before its settings became typed options.
  QSettings().clear();
  QSettings settings;
  settings.setValue(QStringLiteral("layoutPlanning/method"), QStringLiteral("greedy"));
  settings.setValue(QStringLiteral("layoutPlanning/variance"), 0.9);
  settings.setValue(QStringLiteral("layoutPlanning/seed"), 11);
  settings.setValue(QStringLiteral("layoutPlanning/markers"), QStringList{QStringLiteral("lip*"), QStringLiteral("jaw")});
  settings.setValue(QStringLiteral("layoutPlanning/keyPoses"), QStringLiteral("12,40"));
  settings.sync();
  ui::StudioSession session;
  {
    const ui::LayoutPlanningPanel panel(session);
    const ui::LayoutPlanParameters loaded = panel.parameters();
    EXPECT_EQ(loaded.method, SelectionMethod::Greedy);
    EXPECT_DOUBLE_EQ(loaded.variance, 0.9);
    EXPECT_EQ(loaded.seed, 11);
    EXPECT_EQ(loaded.markerPatterns, (QStringList{QStringLiteral("lip*"), QStringLiteral("jaw")}));
    EXPECT_EQ(loaded.keyPoses, QStringLiteral("12,40"));
    EXPECT_EQ(loaded.restarts, ui::LayoutPlanParameters{}.restarts) << "an unsaved one keeps its default";
  }
  QSettings().clear();
}

TEST(SessionViewState, TheHeadStabilizedViewIsTheSessionsAndFollowsTheReferenceMarkers)
{
  QSettings().clear();
  ui::StudioSession session;
  ui::TakeDocument& document = session.document();
  const QString sample = optionsTestPath(test::sampleTake());
  document.open(ui::TakeDocument::read(sample), sample);
  ui::MarkerView3d view(document);
  view.observe(session.view());
  QWidget dialogParent;
  ui::HeadStabilizedViewAction stabilize(document, session.view(), dialogParent);
  QSignalSpy messages(&stabilize, &ui::HeadStabilizedViewAction::message);
  std::vector<Eigen::Index> roots;
  for (const char* label : {"root-1", "root-2", "root-3", "root-4", "root-5", "root-6"})
    roots.push_back(*document.take().markerIndex(label));
  (void)document.setReferenceMarkers(roots);

  stabilize.setOn(true);
  EXPECT_EQ(session.view().headReference(), roots) << "the session's view state holds it";
  EXPECT_EQ(view.headReference(), roots) << "and the view observes it";
  EXPECT_TRUE(stabilize.action()->isChecked());
  (void)document.setReferenceMarkers({roots[0], roots[1]});  // two markers cannot carry a pose
  EXPECT_TRUE(session.view().headReference().empty()) << "back in the lab frame";
  EXPECT_TRUE(view.headReference().empty());
  EXPECT_FALSE(stabilize.action()->isChecked());
  ASSERT_EQ(messages.count(), 2);
  EXPECT_TRUE(messages.last().at(0).toString().contains(QStringLiteral("lab frame")));

  (void)document.setReferenceMarkers(roots);
  EXPECT_TRUE(view.headReference().empty()) << "a new set does not turn it on";
  session.view().setHeadReference(roots);
  EXPECT_TRUE(stabilize.action()->isChecked()) << "the action shows the state, whoever set it";
  stabilize.setOn(false);
  EXPECT_TRUE(view.headReference().empty());
  QSettings().clear();
}

TEST(SessionViewState, TheLayersLookIsTheSessionsAndWhatIsShownIsReadFromIt)
{
  QSettings().clear();
  test::TempDir dir;
  ui::StudioSession session;
  openOptionsTestTake(session, dir.file("take.c3d"));
  ui::MarkerView3d view(session.document());
  ui::SessionScene layers(session, view.scene());  // no panel makes them
  layers.observe(session.view());
  const ui::FaceMeshScene& mesh = layers.faceMesh();
  const ui::BlendshapeScene& rig = layers.blendshapes();
  EXPECT_DOUBLE_EQ(mesh.layer().opacity(), 0.6) << "the studio's first-run look";
  EXPECT_TRUE(rig.shown());
  EXPECT_TRUE(rig.beside());
  ui::ViewState& state = session.view();
  state.setMeshOpacity(0.3);
  state.setMeshEdges(true);
  state.setRigShown(false);
  state.setRigBeside(false);
  EXPECT_DOUBLE_EQ(mesh.layer().opacity(), 0.3) << "the scenes follow the session's view state";
  EXPECT_DOUBLE_EQ(mesh.compareLayer().opacity(), 0.3);
  EXPECT_TRUE(mesh.compareLayer().edgesVisible());
  EXPECT_FALSE(rig.shown());
  EXPECT_FALSE(rig.beside());
  // A review video takes the look from the session, not from a dock's widgets.
  const ui::SceneSettings shown = ui::shownSettings(view, state);
  EXPECT_DOUBLE_EQ(shown.meshOpacity, 0.3);
  EXPECT_TRUE(shown.meshEdges);
  EXPECT_FALSE(shown.rigShown);
  EXPECT_FALSE(shown.rigBeside);
  QSettings().clear();
}

TEST(SessionDocument, SelectsMarkersByLabelAndCountsTheOnesFound)
{
  test::TempDir dir;
  ui::StudioSession session;
  openOptionsTestTake(session, dir.file("take.c3d"));
  EXPECT_EQ(session.document().selectLabels({QStringLiteral(" d"), QStringLiteral("b"), QStringLiteral("zz")}), 2);
  EXPECT_EQ(session.document().selection(), (std::vector<Eigen::Index>{1, 3})) << "trimmed, sorted, unknown left out";
}

TEST(SessionActionsLanguage, TextsMovedOutOfTheWindowKeepTheirTranslations)
{
  auto& app = *QCoreApplication::instance();
  ASSERT_TRUE(studio::installLanguage(app, QStringLiteral("de")));
  const std::pair<const char*, const char*> moved[] = {
      {"MarkerMenus", "&Delete Markers"},
      {"ViewOptionActions", "&Trails"},
      {"RecoveryOffer", "Recover unsaved edits?"},
      {"mocap::ui::TakeFileActions", "Open take"},
      {"mocap::ui::ReferenceMarkerActions", "Reference markers unchanged"},
      {"mocap::ui::CleaningPresetActions", "Save Cleaning Preset"},
      {"mocap::ui::FrameStatusLabel", "Frame %1 of %2–%3 — %4 markers selected"}};
  for (const auto& [context, text] : moved)
    EXPECT_NE(QCoreApplication::translate(context, text), QString::fromUtf8(text)) << context << ": " << text;
  ASSERT_TRUE(studio::installLanguage(app, QStringLiteral("en")));
}

} // namespace
} // namespace mocap
