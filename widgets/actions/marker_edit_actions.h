#pragma once

#include <Eigen/Core>

#include <QObject>
#include <QString>

class QWidget;

namespace mocap::ui {

class TakeDocument;

/// The Edit and Marker menus' edits of markers and samples, each one undoable command on the
/// document's stack: delete markers, add a marker at the mean of others, swap two markers over the
/// selected frame range, make the selected range a gap, and give a point the selected marker's
/// label. An edit that cannot apply to the selection explains why in message() and pushes nothing.
class MarkerEditActions final : public QObject
{
  Q_OBJECT

public:
  /// `dialogParent` parents the dialogs an edit asks with (the label of an averaged marker).
  MarkerEditActions(TakeDocument& document, QWidget& dialogParent, QObject* parent = nullptr);

  /// Marker ▸ Delete Markers: removes the selected markers.
  void deleteMarkers();
  /// Marker ▸ Add Averaged Marker: asks for a label, then inserts the mean of the selection.
  void addAveragedMarker();
  /// Marker ▸ Swap Over Range: exchanges the two selected markers over the selected range.
  void swapOverRange();
  /// Edit ▸ Delete Range: the selected range of the selected markers becomes a gap.
  void deleteRange();
  /// Label ▸ Assign Label by Clicking: the clicked `point` (a fragment) becomes the one selected
  /// marker's samples, and the fragment goes.
  void assignLabel(Eigen::Index point);

signals:
  /// Why an edit did nothing, or what it did, for the status bar (`timeoutMs` 0: until replaced).
  void message(const QString& text, int timeoutMs);

private:
  TakeDocument& m_document;
  QWidget& m_dialogParent;
};

} // namespace mocap::ui
