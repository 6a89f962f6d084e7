#pragma once

#include "panels/cleaning_step.h"

#include <QStringList>
#include <QWidget>

#include <vector>

class QCheckBox;
class QLabel;
class QPushButton;
class QTabWidget;
class QTimer;

namespace mocap::ui {

class JobRunner;
class TakeDocument;

/// The cleaning dock: one tab per step (bad points, gaps, smoothing), each scrolling inside its
/// tab while the preview options, progress, status and Apply stay in view below. Changing a parameter
/// recomputes the step on a worker thread, on a copy of the take, and shows the result as a
/// preview over the views without touching the take; Apply pushes it as one undoable command.
/// A newer request supersedes a running one, and Cancel stops it: the computation itself stops at
/// its next checkpoint (JobRunner) and its result is dropped. Apply on a stale preview computes
/// it first and applies when it arrives, without blocking.
/// After Apply the status says what was done (the step's appliedSummary), not what the next pass
/// would do, until a setting or the take changes again.
/// A detection's flags (bad points) become the document's flags and stay on every tab until the
/// next detection or a repair of them.
class CleaningPanel final : public QWidget
{
  Q_OBJECT

public:
  explicit CleaningPanel(TakeDocument& document, QWidget* parent = nullptr);
  ~CleaningPanel() override;

  void addStep(CleaningStep* step);
  [[nodiscard]] CleaningStep* currentStep() const;
  /// Shows `step` (one added before), which then previews.
  void setCurrentStep(CleaningStep* step);
  /// The added step of type T, or nullptr.
  template <typename T>
  [[nodiscard]] T* step() const
  {
    return findChild<T*>();
  }
  /// Recomputes the preview of the current step now.
  void refresh();
  /// Pushes the current step's result and returns the number of patched samples. On a stale
  /// preview it starts the computation, returns 0 and applies when the preview arrives (unless a
  /// setting or the take changes first, or Cancel).
  int apply();
  /// True while a computation runs.
  [[nodiscard]] bool busy() const;
  /// The panel's background job (its finished() is what a test waits on).
  [[nodiscard]] const JobRunner& jobs() const { return *m_jobs; }
  /// True when the shown result is that of the latest request (nothing running or stale).
  [[nodiscard]] bool previewReady() const { return !busy() && m_resultGeneration == m_generation; }
  /// The added steps, in tab order.
  [[nodiscard]] std::vector<CleaningStep*> steps() const;
  /// The steps' current parameters as `mocap clean` options (a step the panel lacks is off):
  /// what File ▸ Save Cleaning Preset… writes.
  [[nodiscard]] CleanOptions cleanOptions() const;
  /// Sets the steps' parameters from `options` (File ▸ Load Cleaning Preset…): the previews
  /// show them, nothing changes the take until Apply. Head markers in `options` are take
  /// context and are not used. Returns the titles of the steps the preset turns off (left as they
  /// were).
  QStringList loadCleanOptions(const CleanOptions& options);
  [[nodiscard]] const StepResult& lastResult() const { return m_result; }
  /// The status line: what the preview would do, or what the last Apply did.
  [[nodiscard]] QString statusText() const;

protected:
  void showEvent(QShowEvent* event) override;

private:
  void schedule();
  void start();
  void onFinished(unsigned generation, StepResult result);
  void cancel();
  /// What "Selected markers only" and "Selected frame range only" limit the steps to now.
  [[nodiscard]] StepScope scope() const;
  /// Removes the document's flags on samples that `repairs` replace.
  void dropRepairedFlags(const std::vector<SamplePatch>& repairs);
  /// The patches restricted to the selected markers and frame range, when those options are on.
  [[nodiscard]] std::vector<SamplePatch> onlySelected(std::vector<SamplePatch> patches) const;

  TakeDocument& m_document;
  QTabWidget* m_tabs = nullptr;
  QCheckBox* m_live = nullptr;
  QCheckBox* m_selectedOnly = nullptr;
  QCheckBox* m_rangeOnly = nullptr;
  QPushButton* m_apply = nullptr;
  JobRunner* m_jobs = nullptr;
  QLabel* m_status = nullptr;
  QTimer* m_debounce = nullptr;
  StepResult m_result;
  unsigned m_generation = 0;       // bumped by every request and by edits of the take
  unsigned m_runningGeneration = 0;
  unsigned m_resultGeneration = ~0u;
  QString m_applied;        // what the last Apply did, until a setting or the take changes
  bool m_applying = false;  // the Apply's own change of the take keeps m_applied
  bool m_applyWhenReady = false;  // Apply was pressed on a stale preview
};

} // namespace mocap::ui
