#include "panels/gap_list_panel.h"

#include "commands/apply_patches_command.h"
#include "commands/record_step_command.h"
#include "document/job_runner.h"
#include "document/session_option.h"
#include "document/take_document.h"
#include "models/fill_rule_text.h"
#include "models/gap_table_model.h"
#include "panels/job_progress_row.h"
#include "views/label_column.h"

#include "mocap/cleaning/fill/per_gap_fill.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QShortcut>
#include <QSortFilterProxyModel>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <utility>

namespace mocap::ui {

namespace {

/// The dock's remembered check boxes, typed.
struct GapListSettings
{
  SessionOption<bool> livePreview{QStringLiteral("gapList/livePreview"), true};
  SessionOption<bool> onlyOpen{QStringLiteral("gapList/onlyOpen"), false};
};

/// The marker filter (case-insensitive substring of the label) and "only open gaps".
class GapFilterProxy final : public QSortFilterProxyModel
{
public:
  using QSortFilterProxyModel::QSortFilterProxyModel;

  void setLabelFilter(const QString& text)
  {
    m_text = text.trimmed();
    invalidateFilter();
  }
  void setOnlyOpen(bool on)
  {
    m_onlyOpen = on;
    invalidateFilter();
  }

protected:
  bool filterAcceptsRow(int row, const QModelIndex& parent) const override
  {
    const auto* gaps = static_cast<const GapTableModel*>(sourceModel());
    if (m_onlyOpen && gaps->stateAt(row) == GapTableModel::FillState::Filled)
      return false;
    return m_text.isEmpty() ||
           gaps->index(row, GapTableModel::MarkerColumn, parent).data().toString().contains(m_text, Qt::CaseInsensitive);
  }

private:
  QString m_text;
  bool m_onlyOpen = false;
};

/// A combo box of the fill methods for the method column; one choice commits it.
class MethodDelegate final : public QStyledItemDelegate
{
public:
  using QStyledItemDelegate::QStyledItemDelegate;

  QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex&) const override
  {
    auto* combo = new QComboBox(parent);
    for (FillMethod method : allFillMethods()) {
      combo->addItem(GapTableModel::methodTitle(method), static_cast<int>(method));
      combo->setItemData(combo->count() - 1, GapTableModel::methodTip(method), Qt::ToolTipRole);
    }
    connect(combo, qOverload<int>(&QComboBox::activated), this, [this, combo] {
      auto* self = const_cast<MethodDelegate*>(this);  // Qt's delegate signals are non-const
      emit self->commitData(combo);
      emit self->closeEditor(combo);
    });
    return combo;
  }
  void setEditorData(QWidget* editor, const QModelIndex& index) const override
  {
    auto* combo = static_cast<QComboBox*>(editor);
    combo->setCurrentIndex(combo->findData(index.data(Qt::EditRole)));
  }
  void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override
  {
    model->setData(index, static_cast<QComboBox*>(editor)->currentData(), Qt::EditRole);
  }
};

} // namespace

bool GapListPanel::Request::operator==(const Request& other) const
{
  return methods == other.methods && allowed == other.allowed &&
         std::equal(gaps.begin(), gaps.end(), other.gaps.begin(), other.gaps.end(), [](const Gap& a, const Gap& b) {
           return a.marker == b.marker && a.firstFrame == b.firstFrame && a.length == b.length;
         });
}

GapListPanel::GapListPanel(TakeDocument& document, QWidget* parent) : QWidget(parent), m_document(document)
{
  m_model = new GapTableModel(document, this);
  auto* proxy = new GapFilterProxy(this);
  m_proxy = proxy;
  m_proxy->setSourceModel(m_model);
  m_proxy->setSortRole(Qt::UserRole);

  auto* layout = new QVBoxLayout(this);
  auto* filters = new QHBoxLayout;
  m_filter = new QLineEdit(this);
  m_filter->setObjectName(QStringLiteral("gapFilter"));
  m_filter->setPlaceholderText(tr("Filter markers…"));
  m_filter->setClearButtonEnabled(true);
  m_onlyOpen = new QCheckBox(tr("Only open gaps"), this);
  m_onlyOpen->setObjectName(QStringLiteral("onlyOpenGaps"));
  m_onlyOpen->setChecked(GapListSettings().onlyOpen);
  proxy->setOnlyOpen(m_onlyOpen->isChecked());
  filters->addWidget(m_filter, 1);
  filters->addWidget(m_onlyOpen);
  layout->addLayout(filters);

  m_view = new QTableView(this);
  m_view->setModel(m_proxy);
  m_view->setSortingEnabled(true);
  m_view->sortByColumn(-1, Qt::AscendingOrder);  // marker, then frame order until the user sorts
  m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
  m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::SelectedClicked |
                          QAbstractItemView::EditKeyPressed);
  m_view->setItemDelegateForColumn(GapTableModel::MethodColumn, new MethodDelegate(m_view));
  m_view->setContextMenuPolicy(Qt::CustomContextMenu);
  m_view->setWordWrap(false);  // one line per gap; long method names are elided
  m_view->verticalHeader()->hide();
  QHeaderView* header = m_view->horizontalHeader();
  header->setSectionResizeMode(QHeaderView::ResizeToContents);
  // Frame numbers need 5 digits, not their headers' width; states ("allowed: over the 0.5 s limit")
  // and method titles ("Distance-weighted neighbours (Lin–Ouhyoung)") are long: fixed widths, elided,
  // the whole text in the tooltip, so marker, frames, state and override fit the dock as the studio
  // first opens on a 1280×800 screen.
  // Labels from other systems run long ("Skeleton_LShoulder2"): see limitLabelColumn.
  limitLabelColumn(*m_view, GapTableModel::MarkerColumn, true);
  const int digits = m_view->fontMetrics().horizontalAdvance(QStringLiteral("000000"));
  for (const auto& [column, width] :
       {std::pair{GapTableModel::FirstFrameColumn, digits}, std::pair{GapTableModel::LengthColumn, digits},
        std::pair{GapTableModel::StateColumn, 100}, std::pair{GapTableModel::MethodColumn, 110}}) {
    header->setSectionResizeMode(column, QHeaderView::Interactive);
    header->resizeSection(column, width);
  }
  header->setStretchLastSection(true);
  layout->addWidget(m_view, 1);

  auto* checks = new QHBoxLayout;
  auto* checkShown = new QPushButton(tr("Check Shown"), this);
  checkShown->setToolTip(tr("Check every open gap the filter shows"));
  auto* uncheckAll = new QPushButton(tr("Uncheck All"), this);
  m_live = new QCheckBox(tr("Live preview"), this);
  m_live->setChecked(GapListSettings().livePreview);
  m_live->setToolTip(tr("Show the fill of the checked (or selected) gaps over the views before filling"));
  checks->addWidget(checkShown);
  checks->addWidget(uncheckAll);
  checks->addStretch();
  checks->addWidget(m_live);
  layout->addLayout(checks);

  m_jobs = new JobRunner(this);
  layout->addWidget(new JobProgressRow(*m_jobs, this));
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  layout->addWidget(m_status);
  auto* buttons = new QHBoxLayout;
  m_fill = new QPushButton(tr("Fill"), this);
  // Not the button's own shortcut: setText (the button names what it fills) sets a button's
  // shortcut to its text's mnemonic, so Ctrl+Return was gone once a gap was checked.
  auto* fillKey = new QShortcut(QKeySequence(Qt::CTRL | Qt::Key_Return), this);
  connect(fillKey, &QShortcut::activated, m_fill, &QPushButton::animateClick);
  buttons->addStretch();
  buttons->addWidget(m_fill);
  layout->addLayout(buttons);

  m_debounce = new QTimer(this);
  m_debounce->setSingleShot(true);
  m_debounce->setInterval(200);
  connect(m_debounce, &QTimer::timeout, this, &GapListPanel::evaluate);

  connect(m_filter, &QLineEdit::textChanged, this, [proxy](const QString& text) { proxy->setLabelFilter(text); });
  connect(m_onlyOpen, &QCheckBox::toggled, this, [proxy](bool on) {
    proxy->setOnlyOpen(on);
    GapListSettings().onlyOpen.set(on);
  });
  connect(m_live, &QCheckBox::toggled, this, [this](bool on) {
    GapListSettings().livePreview.set(on);
    if (on)
      schedule();
    else
      clearOwnPreview();
  });
  connect(checkShown, &QPushButton::clicked, this, [this] {
    std::vector<int> rows;
    for (int r = 0; r < m_proxy->rowCount(); ++r)
      rows.push_back(m_proxy->mapToSource(m_proxy->index(r, 0)).row());
    m_model->setCheckedRows(rows, true);
  });
  connect(uncheckAll, &QPushButton::clicked, this, [this] { m_model->setCheckedRows(m_model->checkedRows(), false); });
  connect(m_fill, &QPushButton::clicked, this, [this] { fill(); });
  connect(m_jobs, &JobRunner::cancelled, this, &GapListPanel::cancel);
  connect(m_view, &QTableView::activated, this, [this](const QModelIndex& index) {
    if (index.column() != GapTableModel::MethodColumn)  // there a double-click chooses the method
      showGap(m_proxy->mapToSource(index).row());
  });
  connect(m_view, &QTableView::customContextMenuRequested, this, [this](const QPoint& position) {
    const QModelIndex index = m_view->indexAt(position);
    if (!index.isValid())
      return;
    const int row = m_proxy->mapToSource(index).row();
    QMenu menu(this);
    menu.addAction(tr("Show Gap"), this, [this, row] { showGap(row); });
    QAction* fillOne = menu.addAction(tr("Fill This Gap"), this, [this, row] { fill(std::vector<int>{row}); });
    fillOne->setEnabled(m_model->stateAt(row) != GapTableModel::FillState::Filled);
    if (m_model->stateAt(row) != GapTableModel::FillState::Filled && m_model->refusalAt(row) != UnfilledCause::None) {
      QAction* allow = menu.addAction(tr("Allow Filling This Gap"), this,
                                      [this, row](bool on) { m_model->setAllowed(row, on); });
      allow->setCheckable(true);
      allow->setChecked(m_model->isAllowed(row));
      allow->setToolTip(m_model->refusalText(row));
    }
    menu.exec(m_view->viewport()->mapToGlobal(position));
  });
  connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
    updateButtons();
    if (m_model->checkedRows().empty())  // the selection is the scope
      schedule();
  });
  connect(m_model, &GapTableModel::choicesChanged, this, [this] {
    updateButtons();
    schedule();
  });
  // A reset (gaps appeared or went) loses the view's selection: keep it by gap.
  connect(m_model, &QAbstractItemModel::modelAboutToBeReset, this, [this] {
    m_savedSelection.clear();
    for (const QModelIndex& index : m_view->selectionModel()->selectedRows()) {
      const Gap& gap = m_model->gapAt(m_proxy->mapToSource(index).row());
      m_savedSelection.emplace_back(gap.marker, gap.firstFrame);
    }
  });
  connect(m_model, &QAbstractItemModel::modelReset, this, [this] {
    QItemSelection selection;
    for (const auto& [marker, first] : m_savedSelection) {
      const int row = m_model->rowOf(marker, first);
      if (row >= 0) {
        const QModelIndex index = m_proxy->mapFromSource(m_model->index(row, 0));
        selection.select(index, index.siblingAtColumn(GapTableModel::ColumnCount - 1));
      }
    }
    m_view->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    updateButtons();
  });
  connect(&document, &TakeDocument::previewChanged, this, [this] {
    if (!m_settingPreview)
      m_ownsPreview = false;  // another panel's preview now
  });
  connect(&document, &TakeDocument::takeReset, this, &GapListPanel::takeChanged);
  connect(&document, &TakeDocument::markersChanged, this, &GapListPanel::takeChanged);
  connect(&document, &TakeDocument::samplesChanged, this, &GapListPanel::takeChanged);
  updateButtons();
  m_status->setText(tr("Check gaps, or select rows, to preview their fill; double-click a gap to go to it."));
}

GapListPanel::~GapListPanel() = default;  // the runner stops and awaits its job

std::vector<int> GapListPanel::scopeRows() const
{
  std::vector<int> rows = m_model->checkedRows();
  if (!rows.empty())
    return rows;
  for (const QModelIndex& index : m_view->selectionModel()->selectedRows()) {
    const int row = m_proxy->mapToSource(index).row();
    if (m_model->stateAt(row) != GapTableModel::FillState::Filled)
      rows.push_back(row);
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

GapListPanel::Request GapListPanel::requestOf(const std::vector<int>& rows) const
{
  Request request;
  for (int row : rows) {
    if (row < 0 || row >= m_model->rowCount() || m_model->stateAt(row) == GapTableModel::FillState::Filled)
      continue;
    request.gaps.push_back(m_model->gapAt(row));
    request.methods.push_back(m_model->methodAt(row));
    request.allowed.push_back(m_model->isAllowed(row));
  }
  return request;
}

void GapListPanel::showGap(int row)
{
  if (row < 0 || row >= m_model->rowCount())
    return;
  const Gap gap = m_model->gapAt(row);  // a copy: the selection change may rebuild nothing, but be safe
  const Eigen::Index margin = std::max<Eigen::Index>(10, gap.length / 2);
  m_document.setSelection({gap.marker});
  m_document.setCurrentFrame(gap.firstFrame);
  emit frameRangeRequested(static_cast<double>(gap.firstFrame - margin),
                           static_cast<double>(gap.firstFrame + gap.length - 1 + margin));
}

void GapListPanel::updateButtons()
{
  const bool checked = !m_model->checkedRows().empty();
  const auto count = static_cast<int>(scopeRows().size());
  m_fill->setEnabled(count > 0);
  if (count == 0)
    m_fill->setText(tr("Fill"));
  else if (checked)
    m_fill->setText(count == 1 ? tr("Fill 1 Checked Gap") : tr("Fill %1 Checked Gaps").arg(count));
  else
    m_fill->setText(count == 1 ? tr("Fill Selected Gap") : tr("Fill %1 Selected Gaps").arg(count));
  m_fill->setToolTip(tr("Fill the checked gaps, or else the selected ones, each with its method (Ctrl+Return)"));
}

void GapListPanel::schedule()
{
  m_cancelled = false;
  m_debounce->start();
}

void GapListPanel::takeChanged()
{
  ++m_takeGeneration;  // results computed on the old take are stale
  clearOwnPreview();
  updateButtons();
  schedule();
}

void GapListPanel::showEvent(QShowEvent* event)
{
  QWidget::showEvent(event);
  schedule();  // previews are made only while the list is shown
}

void GapListPanel::hideEvent(QHideEvent* event)
{
  QWidget::hideEvent(event);
  clearOwnPreview();  // the views should not show a fill nobody can see the list of
}

bool GapListPanel::busy() const
{
  return m_jobs->running() || m_debounce->isActive() || m_pendingFill.has_value();
}

bool GapListPanel::resultMatches(const Request& request) const
{
  return m_resultTake == m_takeGeneration && m_resultRequest == request;
}

// Decides the next step: push a fill whose result is ready, show a ready preview, or compute
// (superseding a running computation of another request).
void GapListPanel::evaluate()
{
  if (m_cancelled || !m_document.hasTake()) {
    m_pendingFill.reset();
    return;
  }
  const bool filling = m_pendingFill.has_value();
  if (!filling && !(m_live->isChecked() && isVisible())) {
    clearOwnPreview();
    return;
  }
  const Request wanted = filling ? *m_pendingFill : requestOf(scopeRows());
  if (wanted.gaps.empty()) {
    m_pendingFill.reset();
    clearOwnPreview();
    if (filling)
      m_status->setText(tr("No open gap to fill"));
    return;
  }
  if (!resultMatches(wanted)) {
    if (!m_jobs->running() || !(m_running == wanted) || m_runningTake != m_takeGeneration)
      launch(wanted);  // else it is on its way: onFinished evaluates again
    return;
  }
  if (filling) {
    m_pendingFill.reset();
    push();
  } else {
    showPreview();
  }
}

void GapListPanel::launch(const Request& request)
{
  m_running = request;
  m_runningTake = m_takeGeneration;
  m_status->setText(tr("Computing the fill of %n gap(s)…", nullptr, static_cast<int>(request.gaps.size())));
  m_jobs->start(
      [take = m_document.take(), request, rules = m_model->fillRules()](const JobControl& control) {
        return fillEachGap(take, request.gaps, request.methods, request.allowed, rules, control);
      },
      [this, request, take = m_takeGeneration](FillResult result) { onFinished(request, take, std::move(result)); });
}

void GapListPanel::onFinished(const Request& request, unsigned take, FillResult result)
{
  if (m_cancelled)
    return;
  if (take == m_takeGeneration) {  // a valid result for its request, even if no longer wanted
    m_result = std::move(result);
    m_resultRequest = request;
    m_resultTake = take;
    m_model->setReports(m_result.gaps);
  }
  evaluate();
}

void GapListPanel::cancel()
{
  m_cancelled = true;
  m_pendingFill.reset();
  m_debounce->stop();
  m_status->setText(tr("Cancelled"));
}

void GapListPanel::fill(std::optional<std::vector<int>> rows)
{
  m_pendingFill = requestOf(rows ? *rows : scopeRows());
  m_cancelled = false;
  m_debounce->stop();
  evaluate();
}

QString GapListPanel::countsText(bool applied) const
{
  const auto gaps = static_cast<int>(m_result.patches.size());
  int samples = 0;
  for (const SamplePatch& patch : m_result.patches)
    samples += static_cast<int>(patch.size());
  const auto unfilled = static_cast<int>(
      std::count_if(m_result.gaps.begin(), m_result.gaps.end(), [](const GapFillReport& r) { return !r.filled; }));
  // Singular and plural spelled out: the source language has no translation of its own.
  QString text;
  if (gaps > 0) {
    text = applied ? (gaps == 1 ? tr("1 gap filled") : tr("%1 gaps filled").arg(gaps))
                   : (gaps == 1 ? tr("1 gap previewed") : tr("%1 gaps previewed").arg(gaps));
    text += samples == 1 ? tr(", 1 sample") : tr(", %1 samples").arg(samples);
  }
  if (unfilled > 0) {
    const auto first = std::find_if(m_result.gaps.begin(), m_result.gaps.end(),
                                    [](const GapFillReport& r) { return !r.filled; });
    const QString reason = fillRuleText(*first, m_document.take(), m_model->fillRules());
    const QString open = unfilled == 1 ? tr("1 gap left open: %1").arg(reason)
                                       : tr("%1 gaps left open (the first: %2)").arg(unfilled).arg(reason);
    text = text.isEmpty() ? open : tr("%1; %2").arg(text, open);
  }
  return text;
}

void GapListPanel::showPreview()
{
  m_status->setText(countsText(false));
  if (m_result.patches.empty() && !m_ownsPreview)
    return;
  m_settingPreview = true;
  m_document.setPreview(m_result.patches);
  m_settingPreview = false;
  m_ownsPreview = true;
}

void GapListPanel::clearOwnPreview()
{
  if (!m_ownsPreview)
    return;
  m_settingPreview = true;
  m_document.clearPreview();
  m_settingPreview = false;
  m_ownsPreview = false;
}

// "M12 frames 400–711, M3 frames 10–97 and 2 more gaps": the gaps filled past the rules. O(#gaps).
QString GapListPanel::inventedText(const FillResult& result, const Request& request, int& samples) const
{
  const Take& take = m_document.take();
  QStringList where;
  int more = 0;
  samples = 0;
  for (std::size_t i = 0; i < result.gaps.size(); ++i) {
    const Gap& gap = result.gaps[i].gap;
    if (!result.gaps[i].filled || !request.allowed[i])
      continue;
    samples += static_cast<int>(gap.length);
    if (where.size() == 4) {
      ++more;
      continue;
    }
    where << tr("%1 frames %2–%3")
                 .arg(QString::fromStdString(take.label(gap.marker)))
                 .arg(static_cast<qlonglong>(take.firstFrame() + gap.firstFrame))
                 .arg(static_cast<qlonglong>(take.firstFrame() + gap.firstFrame + gap.length - 1));
  }
  QString text = where.join(QStringLiteral(", "));
  if (more > 0)
    text += more == 1 ? tr(" and 1 more gap") : tr(" and %1 more gaps").arg(more);
  return text;
}

void GapListPanel::push()
{
  clearOwnPreview();
  // Copies: the question below runs an event loop, in which a preview may replace the result.
  const FillResult result = m_result;
  const Request request = m_resultRequest;
  const QString counts = countsText(true);
  if (result.patches.empty()) {
    m_status->setText(counts);
    return;
  }
  int invented = 0;
  const QString where = inventedText(result, request, invented);
  if (invented > 0 &&
      QMessageBox::question(this, tr("Fill Past the Rules?"),
                            (invented == 1 ? tr("Invent 1 sample: %1?").arg(where)
                                           : tr("Invent %1 samples: %2?").arg(QString::number(invented), where)) +
                                QStringLiteral("\n\n") +
                                tr("These gaps are longer than the limit, at the take's ends or on a marker seen "
                                   "too rarely: nothing measured them."),
                            QMessageBox::Yes | QMessageBox::No, QMessageBox::No) != QMessageBox::Yes) {
    if (m_live->isChecked() && isVisible())
      showPreview();  // the proposal stays on view
    m_status->setText(tr("Nothing filled: filling past the rules was not confirmed"));
    return;
  }
  QStringList methods;
  for (std::size_t i = 0; i < result.gaps.size(); ++i)
    if (result.gaps[i].filled && !methods.contains(GapTableModel::methodTitle(request.methods[i])))
      methods << GapTableModel::methodTitle(request.methods[i]);
  const auto gaps = static_cast<int>(result.patches.size());
  const QString text = (gaps == 1 ? tr("Fill 1 gap: %1") : tr("Fill %1 gaps: %2").arg(gaps)).arg(methods.join(", "));
  std::vector<std::pair<std::string, std::string>> parameters{{"method", methods.join(", ").toStdString()}};
  if (invented > 0)
    parameters.emplace_back("past the rules", where.toStdString());
  m_document.undoStack()->push(makeRecordedEdit(m_document, result.patches, text, "fill gaps", parameters));
  m_status->setText(counts);  // after the push: the take change schedules a new preview
}

void GapListPanel::setFillRules(const FillOptions& rules)
{
  if (sameFillRules(rules, m_model->fillRules()))
    return;  // e.g. the method changed: not a rule
  m_model->setFillRules(rules);
  takeChanged();  // results computed under the old rules are stale
}

QString GapListPanel::statusText() const
{
  return m_status->text();
}

} // namespace mocap::ui
