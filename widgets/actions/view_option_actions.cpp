#include "actions/view_option_actions.h"

#include "actions/option_toggle.h"
#include "document/studio_options.h"
#include "document/view_state.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QMenu>

#include <algorithm>

namespace mocap::ui {

/// The translation context of the View menu's options.
class ViewOptionActions
{
  Q_DECLARE_TR_FUNCTIONS(ViewOptionActions)
};

namespace {
constexpr int kTrailFramesWhenTurnedOn = 50;

void addUpAxisActions(QMenu& menu, SessionOption<int>& upAxis)
{
  auto* group = new QActionGroup(&menu);
  QAction* yUp = menu.addAction(ViewOptionActions::tr("Y Axis Up"));
  QAction* zUp = menu.addAction(ViewOptionActions::tr("Z Axis Up"));
  for (QAction* action : {yUp, zUp}) {
    action->setCheckable(true);
    group->addAction(action);
  }
  QObject::connect(yUp, &QAction::triggered, yUp, [&upAxis] { upAxis = 1; });
  QObject::connect(zUp, &QAction::triggered, zUp, [&upAxis] { upAxis = 2; });
  upAxis.follow(group, [yUp, zUp](int axis) {
    yUp->setChecked(axis == 1);
    zUp->setChecked(axis == 2);
  });
}
} // namespace

void addViewOptionActions(QMenu& menu, StudioOptions& options, ViewState& view)
{
  menu.addAction(ViewOptionActions::tr("&Reset Camera"), QKeySequence(Qt::CTRL | Qt::Key_R), &view,
                 &ViewState::resetCamera);
  addUpAxisActions(menu, options.upAxis);
  QAction* trails = menu.addAction(ViewOptionActions::tr("&Trails"));
  trails->setCheckable(true);
  options.trailFrames.follow(trails, [trails](int frames) { trails->setChecked(frames > 0); });
  QObject::connect(trails, &QAction::triggered, trails, [&options](bool on) {
    options.trailFrames = on ? std::max(options.trailFrames.get(), kTrailFramesWhenTurnedOn) : 0;
  });
  QAction* links = addOptionToggle(menu, ViewOptionActions::tr("Marker &Links"), options.linksVisible);
  links->setShortcut(QKeySequence(Qt::Key_L));
  QAction* outputs = addOptionToggle(menu, ViewOptionActions::tr("Show &Model Outputs"), options.showModelOutputs);
  outputs->setObjectName(QStringLiteral("showModelOutputsAction"));
  outputs->setToolTip(ViewOptionActions::tr("Draw and gap-list the joint angles, forces, moments, powers and virtual "
                                            "points a C3D file stores as points (they are never cleaned)"));
  QAction* follow = addOptionToggle(menu, ViewOptionActions::tr("&Follow Head"), options.followHead);
  follow->setObjectName(QStringLiteral("followHeadAction"));
  follow->setShortcut(QKeySequence(Qt::Key_F));
  follow->setToolTip(ViewOptionActions::tr("Keep the camera on the head as it moves (the centroid of the head markers)"));
}

} // namespace mocap::ui
