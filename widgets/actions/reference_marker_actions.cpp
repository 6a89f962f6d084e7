#include "actions/reference_marker_actions.h"

#include "commands/set_reference_markers_command.h"
#include "dialogs/reference_markers_dialog.h"
#include "document/take_document.h"
#include "views/status_timeout.h"

#include <QUndoStack>
#include <QWidget>

#include <algorithm>
#include <utility>

namespace mocap::ui {

ReferenceMarkerActions::ReferenceMarkerActions(TakeDocument& document, QWidget& dialogParent, QObject* parent)
    : QObject(parent), m_document(document), m_dialogParent(dialogParent)
{
}

bool ReferenceMarkerActions::change(std::vector<Eigen::Index> markers)
{
  std::sort(markers.begin(), markers.end());
  markers.erase(std::unique(markers.begin(), markers.end()), markers.end());
  if (markers == m_document.referenceMarkers())
    return false;  // an edit that changes nothing pushes nothing
  m_document.undoStack()->push(new SetReferenceMarkersCommand(m_document, std::move(markers)));
  return true;
}

void ReferenceMarkerActions::edit()
{
  if (!m_document.hasTake())
    return;
  ReferenceMarkersDialog dialog(m_document, &m_dialogParent);
  if (dialog.exec() != QDialog::Accepted)
    return;
  if (!change(dialog.chosen()))
    emit message(tr("Reference markers unchanged"), kStatusMessageMs);
}

void ReferenceMarkerActions::setSelected()
{
  if (m_document.selection().size() < 3) {
    emit message(tr("Select at least three head-mounted markers first"), kStatusMessageMs);
    return;
  }
  if (!change(m_document.selection()))
    emit message(tr("The selected markers already are the reference markers"), kStatusMessageMs);
}

void ReferenceMarkerActions::acceptProposed(const std::vector<Eigen::Index>& markers)
{
  if (change(markers))
    emit message(tr("Head markers set; Edit ▸ Undo takes them back"), kStatusMessageMs);
}

} // namespace mocap::ui
