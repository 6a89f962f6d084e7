#include "panels/marker_table_panel.h"

#include "document/take_document.h"
#include "models/marker_table_model.h"
#include "views/label_column.h"

#include <QHeaderView>
#include <QSortFilterProxyModel>

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
  horizontalHeader()->setStretchLastSection(true);
  limitLabelColumn(*this, MarkerTableModel::LabelColumn, false);  // "Valid %" stays in view
  connect(selectionModel(), &QItemSelectionModel::selectionChanged, this, &MarkerTablePanel::takeRowSelection);
  connect(&document, &TakeDocument::selectionChanged, this, &MarkerTablePanel::selectDocumentSelection);
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
