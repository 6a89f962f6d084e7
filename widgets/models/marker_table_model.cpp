#include "models/marker_table_model.h"

#include "commands/rename_marker_command.h"
#include "document/take_document.h"

#include <QColor>
#include <QUndoStack>

#include "mocap/model/gaps.h"
#include "mocap/model/marker_points.h"

namespace mocap::ui {

MarkerTableModel::MarkerTableModel(TakeDocument& document, QObject* parent)
    : QAbstractTableModel(parent), m_document(document)
{
  connect(&document, &TakeDocument::takeReset, this, &MarkerTableModel::rebuild);
  connect(&document, &TakeDocument::markersChanged, this, &MarkerTableModel::rebuild);
  connect(&document, &TakeDocument::flagsChanged, this, &MarkerTableModel::countFlags);
  connect(&document, &TakeDocument::visibilityChanged, this, [this] {
    if (rowCount() > 0)
      emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1), {Qt::ForegroundRole});
  });
  connect(&document, &TakeDocument::samplesChanged, this, &MarkerTableModel::refresh);
  connect(&document, &TakeDocument::markerRenamed, this, [this](Eigen::Index marker) {
    const QModelIndex cell = index(static_cast<int>(marker), LabelColumn);
    emit dataChanged(cell, cell);
  });
  rebuild();
}

int MarkerTableModel::rowCount(const QModelIndex& parent) const
{
  return parent.isValid() ? 0 : static_cast<int>(m_stats.size());
}

int MarkerTableModel::columnCount(const QModelIndex& parent) const
{
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant MarkerTableModel::data(const QModelIndex& index, int role) const
{
  if (!index.isValid() || index.row() >= rowCount())
    return {};
  const auto marker = static_cast<Eigen::Index>(index.row());
  const MarkerStats& stats = m_stats[static_cast<std::size_t>(index.row())];
  if (role == Qt::DisplayRole || (role == Qt::EditRole && index.column() == LabelColumn)) {
    switch (index.column()) {
    case LabelColumn: return QString::fromStdString(m_document.take().label(marker));
    case ValidColumn: return QString::number(stats.validPercent, 'f', 1);
    case GapsColumn: return stats.gaps;
    case LongestGapColumn: return static_cast<qlonglong>(stats.longestGap);
    case BadPointsColumn: return m_badPoints[static_cast<std::size_t>(index.row())];
    default: return {};
    }
  }
  if (role == Qt::UserRole) {  // raw values for sorting
    switch (index.column()) {
    case LabelColumn: return QString::fromStdString(m_document.take().label(marker));
    case ValidColumn: return stats.validPercent;
    case GapsColumn: return stats.gaps;
    case LongestGapColumn: return static_cast<qlonglong>(stats.longestGap);
    case BadPointsColumn: return m_badPoints[static_cast<std::size_t>(index.row())];
    default: return {};
    }
  }
  if (role == Qt::ForegroundRole && m_document.isHidden(marker))
    return QColor(Qt::gray);  // hidden in the 3D view
  if (role == Qt::ToolTipRole && index.column() == LabelColumn && !isMarker(m_document.take(), marker)) {
    const std::string_view type = pointTypeName(m_document.take().pointType(marker));
    return tr("A model output (%1), not a marker: never cleaned; drawn and gap-listed only with View ▸ Show Model "
              "Outputs")
        .arg(QString::fromUtf8(type.data(), static_cast<int>(type.size())));
  }
  if (role == Qt::ToolTipRole && index.column() == LabelColumn)  // the column elides long labels
    return QString::fromStdString(m_document.take().label(marker));
  if (role == Qt::TextAlignmentRole && index.column() != LabelColumn)
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  return {};
}

QVariant MarkerTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
  if (orientation == Qt::Horizontal && role == Qt::ToolTipRole) {  // the whole names of the short headers
    switch (section) {
    case LongestGapColumn: return tr("Longest gap, in frames");
    case BadPointsColumn: return tr("Bad points");
    default: return {};
    }
  }
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
    return QAbstractTableModel::headerData(section, orientation, role);
  // Short, so the dock shows every column whole beside the 3D view (at 1600×1000 it cut the third).
  switch (section) {
  case LabelColumn: return tr("Marker");
  case ValidColumn: return tr("Valid %");
  case GapsColumn: return tr("Gaps");
  case LongestGapColumn: return tr("Longest", "the longest gap");
  case BadPointsColumn: return tr("Bad", "bad points");
  default: return {};
  }
}

Qt::ItemFlags MarkerTableModel::flags(const QModelIndex& index) const
{
  Qt::ItemFlags f = QAbstractTableModel::flags(index);
  if (index.column() == LabelColumn)
    f |= Qt::ItemIsEditable;
  return f;
}

bool MarkerTableModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
  if (role != Qt::EditRole || index.column() != LabelColumn || !index.isValid())
    return false;
  const std::string label = value.toString().trimmed().toStdString();
  const auto marker = static_cast<Eigen::Index>(index.row());
  const Take& take = m_document.take();
  if (label.empty() || label == take.label(marker) || take.markerIndex(label))
    return false;
  m_document.undoStack()->push(new RenameMarkerCommand(m_document, marker, label));
  return true;
}

MarkerTableModel::MarkerStats MarkerTableModel::statsOf(Eigen::Index marker) const
{
  const Take& take = m_document.take();
  MarkerStats stats;
  const auto valid = take.valid().col(marker);
  stats.validPercent = take.frameCount() ? 100.0 * static_cast<double>(valid.count()) / static_cast<double>(take.frameCount()) : 0.0;
  for (const Gap& gap : findGaps(valid, marker)) {
    ++stats.gaps;
    stats.longestGap = std::max(stats.longestGap, gap.length);
  }
  return stats;
}

void MarkerTableModel::rebuild()
{
  beginResetModel();
  m_stats.clear();
  for (Eigen::Index m = 0; m < m_document.take().markerCount(); ++m)
    m_stats.push_back(statsOf(m));
  m_badPoints.assign(m_stats.size(), 0);
  endResetModel();
  countFlags();
}

void MarkerTableModel::countFlags()
{
  std::fill(m_badPoints.begin(), m_badPoints.end(), 0);
  for (const auto& flag : m_document.flags())
    if (flag.first >= 0 && static_cast<std::size_t>(flag.first) < m_badPoints.size())
      ++m_badPoints[static_cast<std::size_t>(flag.first)];
  if (rowCount() > 0)
    emit dataChanged(index(0, BadPointsColumn), index(rowCount() - 1, BadPointsColumn));
}

void MarkerTableModel::refresh(const std::vector<Eigen::Index>& markers)
{
  for (Eigen::Index m : markers) {
    if (m < 0 || m >= static_cast<Eigen::Index>(m_stats.size()))
      continue;
    m_stats[static_cast<std::size_t>(m)] = statsOf(m);
    const int row = static_cast<int>(m);
    emit dataChanged(index(row, ValidColumn), index(row, LongestGapColumn));
  }
}

} // namespace mocap::ui
