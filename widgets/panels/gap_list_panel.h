#pragma once

#include "mocap/cleaning/fill/gap_fill.h"

#include <QWidget>

#include <optional>
#include <vector>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;
class QTimer;

namespace mocap::ui {

class GapTableModel;
class JobRunner;
class TakeDocument;

/// The Gaps dock: every gap of the take in a sortable table (marker, first frame, length in frames
/// and seconds, fill method, state), filtered by marker label and "only open gaps". Double-click
/// (or Enter) selects the gap's marker, moves to its first frame and asks the curves to frame it.
/// The gaps in scope — the checked ones, or else the selected rows — are filled each with its own
/// method on a worker thread (on a copy of the take) and previewed over the views; Fill pushes
/// them as one undoable command. A newer request supersedes a running one; Cancel drops it.
/// The Cleaning panel's fill rules hold here too (setFillRules; mocap::checkFillRules decides):
/// a gap they leave open says why and is filled only when the user allows it (Allow column or
/// the context menu), and Fill then asks before inventing its samples.
class GapListPanel final : public QWidget
{
  Q_OBJECT

public:
  explicit GapListPanel(TakeDocument& document, QWidget* parent = nullptr);
  ~GapListPanel() override;

  [[nodiscard]] GapTableModel* model() const { return m_model; }
  [[nodiscard]] QSortFilterProxyModel* proxy() const { return m_proxy; }
  [[nodiscard]] QTableView* view() const { return m_view; }
  /// The model rows a fill acts on: the checked open gaps, or else the selected open gaps.
  [[nodiscard]] std::vector<int> scopeRows() const;
  /// Selects the marker of the gap in model row `row`, moves to its first frame and emits
  /// frameRangeRequested with a margin around it.
  void showGap(int row);
  /// Fills `rows` (model rows; by default the scope) as one undoable command. Computes first
  /// when the preview is not of exactly these gaps; the command is then pushed when the
  /// computation ends, without blocking.
  void fill(std::optional<std::vector<int>> rows = std::nullopt);
  /// True while a computation runs or waits to run.
  [[nodiscard]] bool busy() const;
  /// The panel's background job (its finished() is what a test waits on).
  [[nodiscard]] const JobRunner& jobs() const { return *m_jobs; }
  /// The rules a gap must pass to be filled without the user's override (the Cleaning panel's
  /// longest gap, extrapolation and least seen). FillOptions' defaults until set.
  void setFillRules(const FillOptions& rules);
  /// The status line: what the last preview or fill did.
  [[nodiscard]] QString statusText() const;

signals:
  /// The curves should show frames [first, last] (0-based).
  void frameRangeRequested(double first, double last);

protected:
  void showEvent(QShowEvent* event) override;
  void hideEvent(QHideEvent* event) override;

private:
  /// The gaps to fill and each one's method.
  struct Request
  {
    std::vector<Gap> gaps;
    std::vector<FillMethod> methods;
    std::vector<bool> allowed;  // the user's override of the rules, per gap
    [[nodiscard]] bool operator==(const Request& other) const;
  };
  [[nodiscard]] Request requestOf(const std::vector<int>& rows) const;
  void schedule();
  void evaluate();
  void launch(const Request& request);
  void onFinished(const Request& request, unsigned take, FillResult result);
  void cancel();
  void push();
  void showPreview();
  void clearOwnPreview();
  void takeChanged();
  void updateButtons();
  [[nodiscard]] bool resultMatches(const Request& request) const;
  [[nodiscard]] QString countsText(bool applied) const;
  /// The gaps of `result` filled past the rules, in words; `samples` gets their sample count.
  [[nodiscard]] QString inventedText(const FillResult& result, const Request& request, int& samples) const;

  TakeDocument& m_document;
  GapTableModel* m_model = nullptr;
  QSortFilterProxyModel* m_proxy = nullptr;
  QTableView* m_view = nullptr;
  QLineEdit* m_filter = nullptr;
  QCheckBox* m_onlyOpen = nullptr;
  QCheckBox* m_live = nullptr;
  QPushButton* m_fill = nullptr;
  JobRunner* m_jobs = nullptr;
  QLabel* m_status = nullptr;
  QTimer* m_debounce = nullptr;

  Request m_running;  // the newest request computing
  unsigned m_runningTake = 0;
  FillResult m_result;
  Request m_resultRequest;
  unsigned m_resultTake = ~0u;
  unsigned m_takeGeneration = 0;  // bumped by every change of the take
  std::optional<Request> m_pendingFill;
  bool m_cancelled = false;
  bool m_ownsPreview = false;
  bool m_settingPreview = false;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> m_savedSelection;  // (marker, first frame) over a reset
};

} // namespace mocap::ui
