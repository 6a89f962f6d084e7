#include "actions/marker_menus.h"

#include "actions/labelling_actions.h"
#include "actions/marker_edit_actions.h"
#include "actions/reference_marker_actions.h"
#include "document/take_document.h"
#include "views/marker_view_3d.h"

#include <QAction>
#include <QCoreApplication>
#include <QMenu>
#include <QMenuBar>

namespace mocap::ui {

/// The translation context of the Marker and Label menus.
class MarkerMenus
{
  Q_DECLARE_TR_FUNCTIONS(MarkerMenus)
};

void addMarkerMenu(QMenuBar& bar, TakeDocument& document, MarkerEditActions& edits, ReferenceMarkerActions& reference)
{
  QMenu* markers = bar.addMenu(MarkerMenus::tr("&Marker"));
  markers->addAction(MarkerMenus::tr("&Delete Markers"), QKeySequence(Qt::CTRL | Qt::Key_Delete), &edits,
                     &MarkerEditActions::deleteMarkers)
      ->setToolTip(MarkerMenus::tr("Remove the selected markers from the take (undoable)"));
  markers->addAction(MarkerMenus::tr("Add &Averaged Marker…"), QKeySequence(Qt::CTRL | Qt::Key_M), &edits,
                     &MarkerEditActions::addAveragedMarker)
      ->setToolTip(MarkerMenus::tr("A virtual marker at the mean of the selected markers"));
  markers->addAction(MarkerMenus::tr("&Swap Over Range"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_X), &edits,
                     &MarkerEditActions::swapOverRange)
      ->setToolTip(MarkerMenus::tr("Exchange the data of the two selected markers over the selected frame range"));
  markers->addSeparator();
  QAction* editReference = markers->addAction(MarkerMenus::tr("&Reference Markers…"),
                                              QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R), &reference,
                                              &ReferenceMarkerActions::edit);
  editReference->setObjectName(QStringLiteral("referenceMarkersAction"));
  editReference->setToolTip(
      MarkerMenus::tr("The head-mounted markers that head stabilization, layout planning and the face mesh use"));
  markers->addAction(MarkerMenus::tr("Set Selected as Reference &Markers"), &reference,
                     &ReferenceMarkerActions::setSelected)
      ->setToolTip(MarkerMenus::tr("Make the selected markers (at least three) the take's reference markers (undoable)"));
  markers->addSeparator();
  markers->addAction(MarkerMenus::tr("&Hide Selected"), QKeySequence(Qt::Key_H), &document,
                     [&document] { document.setHidden(document.selection(), true); });
  markers->addAction(MarkerMenus::tr("Show &All"), QKeySequence(Qt::SHIFT | Qt::Key_H), &document,
                     [&document] { document.showAllMarkers(); });
}

void addLabelMenu(QMenuBar& bar, LabellingActions& labelling, MarkerEditActions& edits, MarkerView3d& view,
                  const std::function<void(const QString&, int)>& message)
{
  QMenu* label = bar.addMenu(MarkerMenus::tr("&Label"));
  label->addAction(MarkerMenus::tr("&Track and Label"), QKeySequence(Qt::CTRL | Qt::Key_T), &labelling,
                   &LabellingActions::trackAndLabel)
      ->setToolTip(MarkerMenus::tr("Re-track the unlabelled points and give them the labels of the take's labelled markers"));
  label->addAction(MarkerMenus::tr("Fix &Swaps…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F), &labelling,
                   &LabellingActions::reviewSwaps)
      ->setToolTip(MarkerMenus::tr("Find frames where two labels exchange and repair the ones you accept"));
  QAction* assign = label->addAction(MarkerMenus::tr("&Assign Label by Clicking"));
  assign->setShortcut(QKeySequence(Qt::Key_A));
  assign->setCheckable(true);
  assign->setToolTip(
      MarkerMenus::tr("Select a marker in the table, then click a point in the 3D view to give it that label"));
  QObject::connect(assign, &QAction::toggled, &view, [&view, message](bool on) {
    view.setLabellingMode(on);
    message(on ? MarkerMenus::tr("Labelling: select a marker in the table, then click the point that is it") : QString(),
            on ? 0 : 1);
  });
  QObject::connect(&view, &MarkerView3d::labelPointClicked, &edits, &MarkerEditActions::assignLabel);
}

} // namespace mocap::ui
