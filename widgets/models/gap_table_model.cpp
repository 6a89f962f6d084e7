#include "models/gap_table_model.h"

#include "document/take_document.h"
#include "models/fill_rule_text.h"
#include "views/sample_colors.h"

#include "mocap/model/valid_runs.h"

#include <QColor>

#include <algorithm>
#include <map>
#include <utility>

namespace mocap::ui {

GapTableModel::GapTableModel(TakeDocument& document, QObject* parent) : QAbstractTableModel(parent), m_document(document)
{
  connect(&document, &TakeDocument::takeReset, this, &GapTableModel::rebuild);
  connect(&document, &TakeDocument::markersChanged, this, &GapTableModel::rebuild);
  connect(&document, &TakeDocument::markerRenamed, this, &GapTableModel::rebuild);
  connect(&document, &TakeDocument::samplesChanged, this, &GapTableModel::rebuild);
  connect(&document, &TakeDocument::visibilityChanged, this, &GapTableModel::rebuild);
  connect(&document, &TakeDocument::previewChanged, this, &GapTableModel::updatePreviewed);
  rebuild();
}

QString GapTableModel::methodTitle(FillMethod method)
{
  switch (method) {
  case FillMethod::Auto: return tr("Auto (best blend)");
  case FillMethod::Rigid: return tr("Rigid neighbours");
  case FillMethod::Pca: return tr("PCA (marker correlations)");
  case FillMethod::Spline: return tr("Cubic spline");
  case FillMethod::Linear: return tr("Linear");
  case FillMethod::Zhang3: return tr("Paper method: three neighbours (Zhang et al., muscle mechanism)");
  case FillMethod::ZhangN: return tr("Paper method: n neighbours (Zhang et al., muscle mechanism)");
  case FillMethod::Guenter: return tr("Neighbour average (Guenter)");
  case FillMethod::LinOuhyoung: return tr("Distance-weighted neighbours (Lin–Ouhyoung)");
  }
  return QString::fromUtf8(fillMethodName(method).data(), static_cast<int>(fillMethodName(method).size()));
}

QString GapTableModel::methodTip(FillMethod method)
{
  switch (method) {
  case FillMethod::Auto:
    return tr("Blends regression on the markers moving most alike and the rigid motion of the nearest ones, "
              "weighted by how well each predicts the marker's own data beside the gap");
  case FillMethod::Rigid: return tr("Carries the rigid motion of the nearest markers seen through the gap");
  case FillMethod::Pca: return tr("Rebuilds the gap from a low-rank model of how all markers move together");
  case FillMethod::Spline: return tr("A cubic curve through two seen samples on each side of the gap");
  case FillMethod::Linear: return tr("A straight line between the samples on each side of the gap");
  case FillMethod::Zhang3:
    return tr("Follows the displacements of the three nearest markers, as skin moves with the muscle below it");
  case FillMethod::ZhangN: return tr("Like three neighbours, with the n nearest markers weighted by distance");
  case FillMethod::Guenter: return tr("Moves the marker by the average displacement of its nearest neighbours");
  case FillMethod::LinOuhyoung: return tr("Moves the marker by its neighbours' displacements, nearer ones weighing more");
  }
  return {};
}

int GapTableModel::rowCount(const QModelIndex& parent) const
{
  return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int GapTableModel::columnCount(const QModelIndex& parent) const
{
  return parent.isValid() ? 0 : ColumnCount;
}

// The open gaps (findGaps) and the runs of filled samples of every listed point
// (TakeDocument::isListed), ordered by point, then first frame. O(#frames · #markers).
std::vector<GapTableModel::Row> GapTableModel::currentRows() const
{
  const Take& take = m_document.take();
  const std::vector<Eigen::Index> points = m_document.listedPoints();  // model outputs only when shown
  const std::vector<Gap> gaps = findGaps(take, points);
  std::vector<Row> rows;
  rows.reserve(gaps.size());
  auto add = [&rows, &take](const Gap& gap, bool filled, SampleState operations) {
    Row row;
    row.gap = gap;
    row.label = take.label(gap.marker);
    row.filled = filled;
    row.operations = operations;
    rows.push_back(std::move(row));
  };
  auto next = gaps.begin();
  for (const Eigen::Index m : points) {
    const std::size_t first = rows.size();
    for (; next != gaps.end() && next->marker == m; ++next)
      add(*next, false, {});
    // Filled by origin: a fill that was smoothed afterwards is still invented data.
    const auto states = take.states().col(m);
    const ValidMask filled = take.valid().col(m) && states.unaryExpr([](std::uint8_t bits) {
      return SampleState::fromBits(bits).origin() == SampleOrigin::Filled;
    });
    if (!filled.any())
      continue;
    for (const ValidRun& run : findValidRuns(filled)) {
      std::uint8_t operations = 0;
      for (Eigen::Index f = run.first; f < run.first + run.length; ++f)
        operations = static_cast<std::uint8_t>(operations | states(f));
      add(Gap{m, run.first, run.length, run.first == 0 || run.first + run.length == take.frameCount()}, true,
          SampleState::fromBits(static_cast<std::uint8_t>(operations & SampleState::kOperationBits)));
    }
    std::sort(rows.begin() + static_cast<std::ptrdiff_t>(first), rows.end(),
              [](const Row& a, const Row& b) { return a.gap.firstFrame < b.gap.firstFrame; });
  }
  return rows;
}

void GapTableModel::judge(std::vector<Row>& rows) const
{
  const Take& take = m_document.take();
  std::vector<Gap> gaps;
  std::vector<Row*> open;
  for (Row& row : rows)
    if (!row.filled) {
      gaps.push_back(row.gap);
      open.push_back(&row);
    }
  std::vector<GapFillReport> reports;
  try {
    reports = checkFillRules(take, gaps, m_rules);
  } catch (const std::exception&) {  // e.g. no frame rate: the fill itself will say so
    reports.clear();
  }
  for (std::size_t i = 0; i < open.size(); ++i) {
    Row& row = *open[i];
    row.refusal = i < reports.size() ? reports[i].cause : UnfilledCause::None;
    row.refusalText = row.refusal == UnfilledCause::None ? QString() : fillRuleText(reports[i], take, m_rules);
    row.allowed = row.allowed && row.refusal != UnfilledCause::None;
  }
}

void GapTableModel::rebuild()
{
  std::vector<Row> rows = currentRows();
  // Carry the user's choices over: a gap keeps its check box and method while other gaps change.
  std::map<std::pair<std::string, Eigen::Index>, const Row*> previous;
  for (const Row& row : m_rows)
    previous.emplace(std::make_pair(row.label, row.gap.firstFrame), &row);
  for (Row& row : rows) {
    const auto it = previous.find({row.label, row.gap.firstFrame});
    if (it == previous.end())
      continue;
    const Row& old = *it->second;
    row.method = old.method;
    if (row.filled || old.filled || old.gap.length != row.gap.length)
      continue;
    row.checked = old.checked;
    row.allowed = old.allowed;
    row.unfillable = old.unfillable;
    row.note = old.note;
  }
  judge(rows);
  const bool sameRows = rows.size() == m_rows.size() &&
                        std::equal(rows.begin(), rows.end(), m_rows.begin(), [](const Row& a, const Row& b) {
                          return a.gap.marker == b.gap.marker && a.gap.firstFrame == b.gap.firstFrame;
                        });
  if (sameRows) {  // e.g. a gap became filled: keep the views' selection and scroll position
    m_rows = std::move(rows);
    if (!m_rows.empty())
      emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
  } else {
    beginResetModel();
    m_rows = std::move(rows);
    endResetModel();
  }
  updatePreviewed();
}

// O(#preview patches + #rows · log(patch size)).
void GapTableModel::updatePreviewed()
{
  std::vector<std::vector<const SamplePatch*>> byMarker(static_cast<std::size_t>(m_document.take().markerCount()));
  for (const SamplePatch& patch : m_document.preview())
    if (patch.marker >= 0 && patch.marker < m_document.take().markerCount())
      byMarker[static_cast<std::size_t>(patch.marker)].push_back(&patch);
  bool changed = false;
  for (Row& row : m_rows) {
    bool previewed = false;
    if (!row.filled && row.gap.marker < static_cast<Eigen::Index>(byMarker.size()))
      for (const SamplePatch* patch : byMarker[static_cast<std::size_t>(row.gap.marker)])
        previewed = previewed || std::binary_search(patch->frames.begin(), patch->frames.end(), row.gap.firstFrame);
    changed = changed || previewed != row.previewed;
    row.previewed = previewed;
  }
  if (changed)
    emit dataChanged(index(0, StateColumn), index(rowCount() - 1, StateColumn));
}

const Gap& GapTableModel::gapAt(int row) const
{
  return m_rows.at(static_cast<std::size_t>(row)).gap;
}

GapTableModel::FillState GapTableModel::stateAt(int row) const
{
  const Row& r = m_rows.at(static_cast<std::size_t>(row));
  if (r.filled)
    return FillState::Filled;
  if (r.previewed)
    return FillState::Previewed;
  return r.unfillable ? FillState::Unfillable : FillState::Open;
}

FillMethod GapTableModel::methodAt(int row) const
{
  return m_rows.at(static_cast<std::size_t>(row)).method;
}

bool GapTableModel::isChecked(int row) const
{
  return m_rows.at(static_cast<std::size_t>(row)).checked;
}

void GapTableModel::setChecked(int row, bool checked)
{
  setCheckedRows({row}, checked);
}

void GapTableModel::setCheckedRows(const std::vector<int>& rows, bool checked)
{
  bool changed = false;
  for (int row : rows) {
    if (row < 0 || row >= rowCount())
      continue;
    Row& r = m_rows[static_cast<std::size_t>(row)];
    if (r.filled || r.checked == checked)
      continue;
    r.checked = checked;
    changed = true;
    emit dataChanged(index(row, MarkerColumn), index(row, MarkerColumn), {Qt::CheckStateRole});
  }
  if (changed)
    emit choicesChanged();
}

void GapTableModel::setMethod(int row, FillMethod method)
{
  Row& r = m_rows.at(static_cast<std::size_t>(row));
  if (r.filled || r.method == method)
    return;
  r.method = method;
  r.unfillable = false;  // the reason was the old method's
  r.note.clear();
  emit dataChanged(index(row, StateColumn), index(row, MethodColumn));
  emit choicesChanged();
}

void GapTableModel::setFillRules(const FillOptions& rules)
{
  m_rules = rules;
  judge(m_rows);
  if (!m_rows.empty())
    emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
  emit choicesChanged();
}

UnfilledCause GapTableModel::refusalAt(int row) const
{
  return m_rows.at(static_cast<std::size_t>(row)).refusal;
}

QString GapTableModel::refusalText(int row) const
{
  return m_rows.at(static_cast<std::size_t>(row)).refusalText;
}

bool GapTableModel::isAllowed(int row) const
{
  return m_rows.at(static_cast<std::size_t>(row)).allowed;
}

void GapTableModel::setAllowed(int row, bool allowed)
{
  Row& r = m_rows.at(static_cast<std::size_t>(row));
  allowed = allowed && !r.filled && r.refusal != UnfilledCause::None;
  if (r.allowed == allowed)
    return;
  r.allowed = allowed;
  emit dataChanged(index(row, StateColumn), index(row, StateColumn));
  emit choicesChanged();
}

std::vector<int> GapTableModel::checkedRows() const
{
  std::vector<int> rows;
  for (std::size_t i = 0; i < m_rows.size(); ++i)
    if (m_rows[i].checked && !m_rows[i].filled)
      rows.push_back(static_cast<int>(i));
  return rows;
}

// Rows are ordered by marker, then first frame: a binary search. O(log #rows).
int GapTableModel::rowOf(Eigen::Index marker, Eigen::Index firstFrame) const
{
  const auto it = std::lower_bound(m_rows.begin(), m_rows.end(), std::make_pair(marker, firstFrame),
                                   [](const Row& row, const std::pair<Eigen::Index, Eigen::Index>& key) {
                                     return std::make_pair(row.gap.marker, row.gap.firstFrame) < key;
                                   });
  if (it == m_rows.end() || it->filled || it->gap.marker != marker || it->gap.firstFrame != firstFrame)
    return -1;
  return static_cast<int>(it - m_rows.begin());
}

void GapTableModel::setReports(const std::vector<GapFillReport>& reports)
{
  for (const GapFillReport& report : reports) {
    const int row = rowOf(report.gap.marker, report.gap.firstFrame);
    if (row < 0 || m_rows[static_cast<std::size_t>(row)].gap.length != report.gap.length)
      continue;
    if (!report.filled && report.cause != UnfilledCause::Method)
      continue;  // left open by the rules: the row says so already
    Row& r = m_rows[static_cast<std::size_t>(row)];
    r.unfillable = !report.filled;
    r.note = QString::fromStdString(report.filled ? report.method : report.reason);
  }
  if (!m_rows.empty())
    emit dataChanged(index(0, StateColumn), index(rowCount() - 1, StateColumn));
}

QString GapTableModel::stateText(const Row& row) const
{
  if (row.filled && !row.operations.untouched())
    return tr("filled (%1)").arg(operationsText(row.operations));
  if (row.filled)
    return tr("filled");
  if (row.previewed)
    return tr("previewed");
  if (row.unfillable)
    return tr("cannot fill: %1").arg(row.note);
  if (row.refusal != UnfilledCause::None)
    return row.allowed ? tr("allowed: %1").arg(row.refusalText) : row.refusalText;
  return tr("open");
}

QVariant GapTableModel::data(const QModelIndex& index, int role) const
{
  if (!index.isValid() || index.row() >= rowCount())
    return {};
  const Row& row = m_rows[static_cast<std::size_t>(index.row())];
  const Take& take = m_document.take();
  const double seconds = static_cast<double>(row.gap.length) / take.frameRate();
  if (role == Qt::DisplayRole) {
    switch (index.column()) {
    case MarkerColumn: return QString::fromStdString(row.label);
    case FirstFrameColumn: return static_cast<qlonglong>(take.firstFrame() + row.gap.firstFrame);
    case LengthColumn: return static_cast<qlonglong>(row.gap.length);
    case SecondsColumn: return QString::number(seconds, 'f', 2);
    case MethodColumn: return row.filled ? QStringLiteral("—") : methodTitle(row.method);
    case StateColumn: return stateText(row);
    default: return {};
    }
  }
  if (role == Qt::UserRole) {  // raw values for sorting
    switch (index.column()) {
    case MarkerColumn: return QString::fromStdString(row.label);
    case FirstFrameColumn: return static_cast<qlonglong>(take.firstFrame() + row.gap.firstFrame);
    case LengthColumn: return static_cast<qlonglong>(row.gap.length);
    case SecondsColumn: return seconds;
    case MethodColumn: return row.filled ? QString() : methodTitle(row.method);
    case StateColumn: return static_cast<int>(stateAt(index.row()));
    default: return {};
    }
  }
  if (role == Qt::EditRole && index.column() == MethodColumn)
    return static_cast<int>(row.method);
  if (role == Qt::CheckStateRole && index.column() == MarkerColumn && !row.filled)
    return row.checked ? Qt::Checked : Qt::Unchecked;
  const bool overridable = !row.filled && row.refusal != UnfilledCause::None;
  if (role == Qt::CheckStateRole && index.column() == StateColumn && overridable)
    return row.allowed ? Qt::Checked : Qt::Unchecked;
  if (role == Qt::ToolTipRole && index.column() == MarkerColumn)  // the column elides long labels
    return data(index, Qt::DisplayRole);
  if (role == Qt::ToolTipRole && index.column() == StateColumn && overridable)
    return tr("Left open by the fill rules (%1). Check to fill it anyway: Fill asks before inventing its samples")
        .arg(row.refusalText);
  if (role == Qt::ToolTipRole && index.column() == StateColumn)  // the column is narrow: the whole text
    return row.note.isEmpty() ? stateText(row) : row.unfillable ? row.note : tr("Filled by: %1").arg(row.note);
  if (role == Qt::ToolTipRole && index.column() == MethodColumn && !row.filled)
    return tr("%1: %2. Double-click to choose how this gap is filled")
        .arg(methodTitle(row.method), methodTip(row.method));
  if (role == Qt::ForegroundRole) {
    if (row.filled)
      return QColor(Qt::gray);
    if (index.column() == StateColumn && !row.previewed &&
        (row.unfillable || (row.refusal != UnfilledCause::None && !row.allowed)))
      return QColor(190, 40, 40);
  }
  if (role == Qt::TextAlignmentRole && (index.column() == FirstFrameColumn || index.column() == LengthColumn ||
                                        index.column() == SecondsColumn))
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  return {};
}

QVariant GapTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
  if (orientation == Qt::Horizontal && role == Qt::ToolTipRole) {
    switch (section) {
    case MarkerColumn: return tr("Check the gaps to fill together");
    case FirstFrameColumn: return tr("First missing frame (the file's numbering)");
    case LengthColumn: return tr("Length in frames");
    case SecondsColumn: return tr("Length in seconds");
    case MethodColumn: return tr("How the gap is filled (double-click to choose)");
    case StateColumn:
      return tr("Open, previewed, filled, or why it is not filled. A gap the rules leave open (too long, at the "
                "take's ends, a marker seen too rarely) has a box: check it to fill the gap anyway");
    default: return {};
    }
  }
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
    return QAbstractTableModel::headerData(section, orientation, role);
  switch (section) {  // short: the dock is narrow
  case MarkerColumn: return tr("Marker");
  case FirstFrameColumn: return tr("First");
  case LengthColumn: return tr("Frames");
  case SecondsColumn: return tr("s");
  case MethodColumn: return tr("Method");
  case StateColumn: return tr("State");
  default: return {};
  }
}

Qt::ItemFlags GapTableModel::flags(const QModelIndex& index) const
{
  Qt::ItemFlags flags = QAbstractTableModel::flags(index);
  if (!index.isValid() || m_rows[static_cast<std::size_t>(index.row())].filled)
    return flags;
  if (index.column() == MarkerColumn)
    flags |= Qt::ItemIsUserCheckable;
  if (index.column() == MethodColumn)
    flags |= Qt::ItemIsEditable;
  if (index.column() == StateColumn && m_rows[static_cast<std::size_t>(index.row())].refusal != UnfilledCause::None)
    flags |= Qt::ItemIsUserCheckable;
  return flags;
}

bool GapTableModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
  if (!index.isValid() || index.row() >= rowCount() || m_rows[static_cast<std::size_t>(index.row())].filled)
    return false;
  if (role == Qt::CheckStateRole && index.column() == MarkerColumn) {
    setChecked(index.row(), static_cast<Qt::CheckState>(value.toInt()) == Qt::Checked);
    return true;
  }
  if (role == Qt::CheckStateRole && index.column() == StateColumn) {
    setAllowed(index.row(), static_cast<Qt::CheckState>(value.toInt()) == Qt::Checked);
    return true;
  }
  if (role == Qt::EditRole && index.column() == MethodColumn) {
    const auto& methods = allFillMethods();
    const int method = value.toInt();
    if (method < 0 || method >= static_cast<int>(methods.size()))
      return false;
    setMethod(index.row(), methods[static_cast<std::size_t>(method)]);
    return true;
  }
  return false;
}

} // namespace mocap::ui
