#include "actions/marker_edit_actions.h"

#include "commands/apply_patches_command.h"
#include "commands/insert_marker_command.h"
#include "commands/record_step_command.h"
#include "commands/remove_markers_command.h"
#include "document/take_document.h"
#include "views/status_timeout.h"

#include "mocap/model/marker_edits.h"

#include <QInputDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QStringList>
#include <QUndoCommand>
#include <QUndoStack>
#include <QWidget>

namespace mocap::ui {

MarkerEditActions::MarkerEditActions(TakeDocument& document, QWidget& dialogParent, QObject* parent)
    : QObject(parent), m_document(document), m_dialogParent(dialogParent)
{
}

void MarkerEditActions::deleteMarkers()
{
  if (m_document.selection().empty()) {
    emit message(tr("Select the markers to delete first"), kStatusMessageMs);
    return;
  }
  m_document.undoStack()->push(new RemoveMarkersCommand(m_document, m_document.selection()));
}

void MarkerEditActions::addAveragedMarker()
{
  const auto& selection = m_document.selection();
  if (selection.empty()) {
    emit message(tr("Select the markers to average first"), kStatusMessageMs);
    return;
  }
  const Take& take = m_document.take();
  QStringList sources;
  for (Eigen::Index m : selection)
    sources << QString::fromStdString(take.label(m));
  bool ok = false;
  const QString label = QInputDialog::getText(&m_dialogParent, tr("Add Averaged Marker"),
                                              tr("Label of the marker at the mean of %1:").arg(sources.join(", ")),
                                              QLineEdit::Normal, QStringLiteral("avg_") + sources.join('_'), &ok)
                            .trimmed();
  if (!ok)
    return;
  if (label.isEmpty() || take.markerIndex(label.toStdString())) {
    QMessageBox::warning(&m_dialogParent, tr("Add Averaged Marker"),
                         tr("'%1' is empty or already a marker label; choose another.").arg(label));
    return;
  }
  MarkerColumn column = averagedMarker(take, selection, label.toStdString());
  m_document.undoStack()->push(
      new InsertMarkerCommand(m_document, std::move(column), tr("Add averaged marker %1").arg(label)));
  m_document.setSelection({m_document.take().markerCount() - 1});
}

void MarkerEditActions::swapOverRange()
{
  const auto& selection = m_document.selection();
  if (selection.size() != 2 || !m_document.hasRange()) {
    emit message(tr("Select exactly two markers and Shift-drag a frame range on the curves first"), kStatusMessageMs);
    return;
  }
  const Take& take = m_document.take();
  const Eigen::Index first = m_document.rangeFirst(), last = m_document.rangeLast();
  const Eigen::Index length = last - first + 1;
  if (!take.valid().col(selection[0]).segment(first, length).any() &&
      !take.valid().col(selection[1]).segment(first, length).any()) {
    emit message(tr("Nothing to swap: both markers are gaps over the selected range"), kStatusMessageMs);
    return;
  }
  auto patches = swapMarkersOverRange(take, selection[0], selection[1], first, last);
  m_document.undoStack()->push(makeRecordedEdit(
      m_document, std::move(patches),
      tr("Swap %1 and %2 over frames %3–%4")
          .arg(QString::fromStdString(take.label(selection[0])), QString::fromStdString(take.label(selection[1])))
          .arg(static_cast<qlonglong>(take.firstFrame() + first))
          .arg(static_cast<qlonglong>(take.firstFrame() + last)),
      "swap markers", {{"markers", take.label(selection[0]) + ", " + take.label(selection[1])}}));
}

void MarkerEditActions::deleteRange()
{
  if (!m_document.hasRange() || m_document.selection().empty()) {
    emit message(tr("Select markers and Shift-drag a frame range on the curves first"), kStatusMessageMs);
    return;
  }
  const Take& take = m_document.take();
  const Eigen::Index first = m_document.rangeFirst(), last = m_document.rangeLast();
  std::vector<SamplePatch> patches;
  for (Eigen::Index m : m_document.selection()) {
    SamplePatch patch = deleteSamples(take, m, first, last);
    if (!patch.empty())
      patches.push_back(std::move(patch));
  }
  if (patches.empty()) {
    emit message(tr("Nothing to delete: the selected range is already a gap"), kStatusMessageMs);
    return;
  }
  m_document.undoStack()->push(makeRecordedEdit(m_document, std::move(patches),
                                                tr("Delete frames %1–%2")
                                                    .arg(static_cast<qlonglong>(take.firstFrame() + first))
                                                    .arg(static_cast<qlonglong>(take.firstFrame() + last)),
                                                "delete samples", {}));
}

void MarkerEditActions::assignLabel(Eigen::Index point)
{
  const Take& take = m_document.take();
  const auto& selection = m_document.selection();
  if (selection.size() != 1 || selection.front() == point) {
    emit message(tr("Select the one marker whose label the point gets, then click the point"), kStatusMessageMs);
    return;
  }
  const Eigen::Index target = selection.front();
  auto* command = new QUndoCommand(
      tr("Label %1 as %2").arg(QString::fromStdString(take.label(point)), QString::fromStdString(take.label(target))));
  // The fragment's samples go to the marker, then the fragment goes; undo runs the children
  // backwards, so the fragment is back before the marker's samples are.
  new ApplyPatchesCommand(m_document, {validSamplesPatch(take, point, target)}, QString(), command);
  new RemoveMarkersCommand(m_document, {point}, command);
  m_document.undoStack()->push(command);
}

} // namespace mocap::ui
