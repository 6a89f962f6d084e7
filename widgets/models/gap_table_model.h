#pragma once

#include "mocap/cleaning/fill/gap_fill.h"
#include "mocap/model/gaps.h"

#include <QAbstractTableModel>
#include <QString>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mocap::ui {

class TakeDocument;

/// One row per gap of the take's listed points (TakeDocument::isListed: model outputs only while
/// they are shown), plus one per run of filled samples
/// so a fill stays in the list, marked "filled", until it is undone. Each open gap carries the
/// user's choices: a check box (MarkerColumn, Qt::CheckStateRole) and a fill method
/// (MethodColumn, Qt::EditRole gives and takes the FillMethod as int); they are view state, not
/// edits, and survive edits of other gaps (kept by marker label and first frame). The state column
/// says open, previewed (the document's preview covers the gap), filled, or why the last fill
/// computation could not fill it. The fill rules (mocap::checkFillRules with the Cleaning panel's
/// longest gap, least seen and extrapolation; FillOptions' defaults until setFillRules) leave some
/// gaps open: their state says why ("over the 0.5 s limit") and the Allow column
/// (Qt::CheckStateRole) is the user's per-gap override. Sort through a QSortFilterProxyModel on Qt::UserRole (raw
/// values). Rebuilt on every change of the take: O(#frames · #markers).
class GapTableModel final : public QAbstractTableModel
{
  Q_OBJECT

public:
  /// In the order a technician reads a gap in a narrow dock: which, where, how long, what will
  /// happen to it; the method and the length in seconds last. A gap the fill rules leave open has
  /// its override box in the state column, beside the reason it overrides.
  enum Column
  {
    MarkerColumn,
    FirstFrameColumn,
    LengthColumn,
    StateColumn,
    MethodColumn,
    SecondsColumn,
    ColumnCount
  };
  enum class FillState
  {
    Open,
    Previewed,
    Unfillable,
    Filled,
  };

  explicit GapTableModel(TakeDocument& document, QObject* parent = nullptr);

  [[nodiscard]] int rowCount(const QModelIndex& parent = {}) const override;
  [[nodiscard]] int columnCount(const QModelIndex& parent = {}) const override;
  [[nodiscard]] QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
  [[nodiscard]] Qt::ItemFlags flags(const QModelIndex& index) const override;
  bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

  /// The gap of `row` (for a filled row, the run of filled samples).
  [[nodiscard]] const Gap& gapAt(int row) const;
  [[nodiscard]] FillState stateAt(int row) const;
  [[nodiscard]] FillMethod methodAt(int row) const;
  [[nodiscard]] bool isChecked(int row) const;
  void setChecked(int row, bool checked);
  void setMethod(int row, FillMethod method);
  /// Checks or unchecks every open gap among `rows`.
  void setCheckedRows(const std::vector<int>& rows, bool checked);
  /// The checked open gaps, in row order.
  [[nodiscard]] std::vector<int> checkedRows() const;
  /// The row of the open gap of `marker` that starts at `firstFrame`, or −1.
  [[nodiscard]] int rowOf(Eigen::Index marker, Eigen::Index firstFrame) const;
  /// The rules gaps are judged by (only longest gap, extrapolation and least seen matter).
  void setFillRules(const FillOptions& rules);
  [[nodiscard]] const FillOptions& fillRules() const { return m_rules; }
  /// Why the rules leave the open gap of `row` open (None: they let it be filled).
  [[nodiscard]] UnfilledCause refusalAt(int row) const;
  /// The rule's reason in words ("over the 0.5 s limit"); empty when none applies.
  [[nodiscard]] QString refusalText(int row) const;
  /// The user's override of the rules for the gap of `row`; only a refused gap can be allowed.
  [[nodiscard]] bool isAllowed(int row) const;
  void setAllowed(int row, bool allowed);
  /// What the last fill computation found for these gaps: the reason of each it could not fill,
  /// the method (auto names its ingredients) of each it could.
  void setReports(const std::vector<GapFillReport>& reports);

  /// The method's name in the UI, e.g. "Rigid neighbours".
  [[nodiscard]] static QString methodTitle(FillMethod method);
  /// What the method does, in one line (its tooltip wherever methods are chosen).
  [[nodiscard]] static QString methodTip(FillMethod method);

signals:
  /// A check box or a method changed: what a fill of the checked gaps would do changed.
  void choicesChanged();

private:
  struct Row
  {
    Gap gap;
    std::string label;
    bool filled = false;  // a run of filled samples, not a gap
    SampleState operations;  // of a filled run: every operation done to some of its samples since
    bool checked = false;
    bool allowed = false;  // filled even though the rules leave it open
    UnfilledCause refusal = UnfilledCause::None;
    QString refusalText;
    FillMethod method = FillOptions{}.method;
    bool previewed = false;
    bool unfillable = false;
    QString note;  // the reason it cannot be filled, or what would fill it
  };
  void rebuild();
  void updatePreviewed();
  /// Judges the open gaps of `rows` by m_rules. O(#frames · #markers).
  void judge(std::vector<Row>& rows) const;
  [[nodiscard]] std::vector<Row> currentRows() const;
  [[nodiscard]] QString stateText(const Row& row) const;

  TakeDocument& m_document;
  FillOptions m_rules;
  std::vector<Row> m_rows;
};

} // namespace mocap::ui
