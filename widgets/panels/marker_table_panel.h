#pragma once

#include <QTableView>

class QSortFilterProxyModel;

namespace mocap::ui {

class MarkerTableModel;
class TakeDocument;

/// The Markers dock: the take's markers (MarkerTableModel) in file order until a column header
/// sorts them, rows selected with the document's selection both ways (selecting rows selects
/// the markers; a selection made elsewhere selects and shows the rows). O(#markers) per change.
class MarkerTablePanel final : public QTableView
{
  Q_OBJECT

public:
  explicit MarkerTablePanel(TakeDocument& document, QWidget* parent = nullptr);

  /// Edit ▸ Rename Marker: edits the current row's label.
  void editCurrentLabel();

  /// As wide as every column whole (the label column at its limit, the others as their header or
  /// values need) with the frame and the vertical scroll bar: the width the studio gives the dock
  /// when it can (a 217 px dock cut its third column at 1600×1000). O(#columns · shown rows).
  [[nodiscard]] QSize sizeHint() const override;

private:
  void selectDocumentSelection();
  void takeRowSelection();

  TakeDocument& m_document;
  MarkerTableModel* m_model = nullptr;
  QSortFilterProxyModel* m_proxy = nullptr;
  bool m_syncing = false;  // while the rows follow the document
};

} // namespace mocap::ui
