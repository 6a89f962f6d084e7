#pragma once

#include "mocap/base/job_control.h"

#include <QElapsedTimer>
#include <QFuture>
#include <QObject>
#include <QString>

#include <atomic>
#include <functional>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

template <typename T>
class QFutureWatcher;

namespace mocap::ui {

/// The background job of a panel or dialog. start(work, deliver) runs `work` on Qt's thread pool
/// with a JobControl (progress, cancel) and hands its result to `deliver` on the UI thread.
/// - Newest request wins: start() while a job runs cancels the older one (it stops at its next
///   checkpoint), and only the newest job's result is ever delivered.
/// - cancel() (the Cancel button) asks the running job to stop and emits cancelled() at once. A
///   job that throws JobCancelled then ends without a result; one that returns what it has (a
///   partial plan, an export that removed its files) is delivered as usual.
/// - A job that throws anything else ends with failed(message).
/// - progressed() carries the fraction done and the time left; finished() follows every end of
///   the newest job (delivered, failed or cancelled), which is the signal a test waits on.
/// `work` runs on a worker: it must own its data (copies, shared pointers), never touch the
/// requester's widgets. O(1) per call, beside the work itself.
class JobRunner final : public QObject
{
  Q_OBJECT

public:
  explicit JobRunner(QObject* parent = nullptr);
  /// Cancels the running job and waits for every job this runner started to end (their progress
  /// is posted to the runner).
  ~JobRunner() override;

  /// Starts `work(const JobControl&) -> R` (copyable, R movable) on a worker and, when it ends as
  /// the newest job, calls `deliver(R)` on this thread.
  template <typename Work, typename Deliver>
  void start(Work work, Deliver deliver);
  /// Asks the running job to stop at its next checkpoint; nothing when none runs.
  void cancel();
  /// Blocks this thread until the running job ends and delivers it at once, without serving the
  /// event loop (the command line's start-up, which has nothing to paint yet).
  void wait();
  /// True from start() until the newest job has ended and been handled.
  [[nodiscard]] bool running() const { return m_watcher != nullptr; }
  /// True after cancel() until the running job ends.
  [[nodiscard]] bool cancelling() const { return running() && m_cancel && m_cancel->load(); }
  /// The running job's last reported fraction (0…1) and time left ("" while too early to tell).
  [[nodiscard]] double fraction() const { return m_fraction; }
  [[nodiscard]] QString timeLeft() const { return m_timeLeft; }

signals:
  void started();
  void progressed(double fraction, const QString& timeLeft);
  void cancelled();
  void failed(const QString& message);
  void finished();

private:
  /// What a worker hands back: the delivery of its result, or why there is none.
  struct Outcome
  {
    std::function<void()> deliver;  // empty when cancelled or failed
    QString error;
  };
  using ErasedWork = std::function<Outcome(const JobControl&)>;

  void launch(ErasedWork work);
  void onEnded(QFutureWatcher<Outcome>* watcher);
  void showProgress(unsigned job, double fraction);

  QFutureWatcher<Outcome>* m_watcher = nullptr;  // the newest job's; null when none runs
  std::shared_ptr<std::atomic<bool>> m_cancel;   // the newest job's
  std::vector<QFuture<Outcome>> m_jobs;          // every job that may still run (awaited on destruction)
  unsigned m_job = 0;                            // progress from an older job is ignored
  QElapsedTimer m_clock;
  double m_fraction = 0.0;
  QString m_timeLeft;
};

template <typename Work, typename Deliver>
void JobRunner::start(Work work, Deliver deliver)
{
  using Result = std::invoke_result_t<Work&, const JobControl&>;
  static_assert(!std::is_void_v<Result>, "a job returns its result");
  launch([work = std::move(work), deliver = std::move(deliver)](const JobControl& control) mutable {
    auto result = std::make_shared<Result>(work(control));
    return Outcome{[deliver, result]() mutable { deliver(std::move(*result)); }, {}};
  });
}

/// "about 12 s left" after `elapsedSeconds` at `fraction` done; empty while too early to tell
/// (under 0.5 s or 2 % done). Assumes the job runs at an even pace. O(1).
[[nodiscard]] QString timeLeftText(double fraction, double elapsedSeconds);

} // namespace mocap::ui
