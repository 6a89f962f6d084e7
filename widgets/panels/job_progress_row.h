#pragma once

#include "mocap/base/job_control.h"

#include <QElapsedTimer>
#include <QWidget>

#include <atomic>
#include <memory>

class QLabel;
class QProgressBar;
class QPushButton;

namespace mocap::ui {

/// The progress bar, time-left estimate and Cancel button of a panel's background job. begin()
/// hands out the JobControl the worker passes to the core step: its progress moves the bar (from
/// any thread) and Cancel stops the computation itself. One job at a time; a begin() while one
/// runs cancels the older one.
class JobProgressRow final : public QWidget
{
  Q_OBJECT

public:
  explicit JobProgressRow(QWidget* parent = nullptr);

  /// Shows the row for a new job and returns its control.
  [[nodiscard]] JobControl begin();
  /// Hides the row (the job delivered, failed or was dropped).
  void finish();
  /// Stops the running job at its next checkpoint and emits cancelled() (the Cancel button).
  void cancel();
  /// Stops the running job at its next checkpoint, silently (a newer request supersedes it).
  void stopRunning();
  [[nodiscard]] bool running() const { return m_cancel != nullptr; }
  [[nodiscard]] QPushButton* cancelButton() const { return m_cancelButton; }
  /// The text of the time estimate ("about 12 s left"); empty until one is known. For tests.
  [[nodiscard]] QString estimateText() const;

signals:
  void cancelled();

private:
  /// Moves the bar for `job` (ignored when another job runs now or none does).
  void showProgress(unsigned job, double fraction);

  QProgressBar* m_bar = nullptr;
  QLabel* m_estimate = nullptr;
  QPushButton* m_cancelButton = nullptr;
  QElapsedTimer m_clock;
  std::shared_ptr<std::atomic<bool>> m_cancel;
  unsigned m_job = 0;  // progress from an older job is ignored
};

/// "about 12 s left" after `elapsedSeconds` at `fraction` done; empty while too early to tell
/// (under 0.5 s or 2 % done). Assumes the job runs at an even pace. O(1).
[[nodiscard]] QString timeLeftText(double fraction, double elapsedSeconds);

} // namespace mocap::ui
