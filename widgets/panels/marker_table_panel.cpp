#include "panels/marker_table_panel.h"

#include "document/take_document.h"
#include "models/marker_table_model.h"
#include "views/label_column.h"

#include <QHeaderView>
#include <QScrollBar>
#include <QSortFilterProxyModel>

#include <algorithm>
#include <utility>
#include <vector>

namespace mocap::ui {

MarkerTablePanel::MarkerTablePanel(TakeDocument& document, QWidget* parent)
    : QTableView(parent), m_document(document), m_model(new MarkerTableModel(document, this)),
      m_proxy(new QSortFilterProxyModel(this))
{
  m_proxy->setSourceModel(m_model);
  m_proxy->setSortRole(Qt::UserRole);
  setModel(m_proxy);
  setSortingEnabled(true);
  sortByColumn(-1, Qt::AscendingOrder);  // file order until the user sorts
  setSelectionBehavior(QAbstractItemView::SelectRows);
  setSelectionMode(QAbstractItemView::ExtendedSelection);
  verticalHeader()->hide();
  horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  // No stretched last column: stretched, it kept the header's default 100 px however little it held
  // and ended past the dock that sizeHint() asked for.
  horizontalHeader()->setStretchLastSection(false);
  limitLabelColumn(*this, MarkerTableModel::LabelColumn, false);  // "Valid %" stays in view
  connect(selectionModel(), &QItemSelectionModel::selectionChanged, this, &MarkerTablePanel::takeRowSelection);
  connect(&document, &TakeDocument::selectionChanged, this, &MarkerTablePanel::selectDocumentSelection);
}

QSize MarkerTablePanel::sizeHint() const
{
  const QHeaderView* header = horizontalHeader();
  int width = 2 * frameWidth() + verticalScrollBar()->sizeHint().width();
  for (int column = 0; column < header->count(); ++column)
    width += column == MarkerTableModel::LabelColumn
                 ? header->sectionSize(column)  // limited, elided beyond
                 : std::max(header->sectionSizeHint(column), sizeHintForColumn(column));
  return {width, QTableView::sizeHint().height()};
}

void MarkerTablePanel::editCurrentLabel()
{
  const QModelIndex current = currentIndex();
  if (current.isValid())
    edit(current.siblingAtColumn(MarkerTableModel::LabelColumn));
}

void MarkerTablePanel::takeRowSelection()
{
  if (m_syncing)
    return;
  std::vector<Eigen::Index> markers;
  for (const QModelIndex& row : selectionModel()->selectedRows())
    markers.push_back(m_proxy->mapToSource(row).row());
  m_document.setSelection(std::move(markers));
}

void MarkerTablePanel::selectDocumentSelection()
{
  m_syncing = true;
  QItemSelection selection;
  for (Eigen::Index m : m_document.selection()) {
    const QModelIndex row = m_proxy->mapFromSource(m_model->index(static_cast<int>(m), 0));
    selection.select(row, row.siblingAtColumn(MarkerTableModel::ColumnCount - 1));
  }
  selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
  if (!m_document.selection().empty())
    scrollTo(m_proxy->mapFromSource(m_model->index(static_cast<int>(m_document.selection().front()), 0)));
  m_syncing = false;
}

} // namespace mocap::ui
