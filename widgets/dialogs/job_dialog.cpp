#include "dialogs/job_dialog.h"

#include "panels/job_progress_row.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFutureWatcher>
#include <QPointer>
#include <QProgressDialog>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>

namespace mocap::ui {

namespace {
int runningJobs = 0;  // runJob calls in progress (UI thread only)

// Counts one running job for its lifetime, however runJob returns.
struct RunningJob
{
  RunningJob() { ++runningJobs; }
  ~RunningJob() { --runningJobs; }
  RunningJob(const RunningJob&) = delete;
  RunningJob& operator=(const RunningJob&) = delete;
};
} // namespace

bool jobRunning()
{
  return runningJobs > 0;
}

bool runJob(QWidget* parent, const QString& label, const std::function<void(const JobControl&)>& work)
{
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  QProgressDialog dialog(label, QProgressDialog::tr("Cancel"), 0, 1000, parent);
  dialog.setWindowModality(Qt::WindowModal);
  dialog.setMinimumDuration(std::numeric_limits<int>::max());  // shown below, not by itself
  dialog.setAutoClose(false);
  dialog.setAutoReset(false);
  QObject::connect(&dialog, &QProgressDialog::canceled, [cancel] { *cancel = true; });
  dialog.setValue(0);

  QElapsedTimer clock;
  clock.start();
  QPointer<QProgressDialog> shown(&dialog);
  auto progress = [shown, clock, label](double fraction) {  // on the worker: post to the UI thread
    QMetaObject::invokeMethod(
        qApp, [shown, clock, label, fraction] {
          QProgressDialog* target = shown.data();
          if (target == nullptr || target->wasCanceled())
            return;
          target->setValue(static_cast<int>(std::lround(1000.0 * fraction)));
          const QString left = timeLeftText(fraction, static_cast<double>(clock.elapsed()) * 1e-3);
          target->setLabelText(left.isEmpty() ? label : label + QLatin1Char('\n') + left);
        },
        Qt::QueuedConnection);
  };
  const JobControl control(std::move(progress), cancel);

  bool cancelled = false;
  std::exception_ptr failure;
  const RunningJob running;
  QEventLoop loop;
  QFutureWatcher<void> watcher;
  QObject::connect(&watcher, &QFutureWatcher<void>::finished, &loop, &QEventLoop::quit);
  watcher.setFuture(QtConcurrent::run([&work, &control, &cancelled, &failure] {
    try {
      work(control);
    } catch (const JobCancelled&) {
      cancelled = true;
    } catch (...) {
      failure = std::current_exception();
    }
  }));
  // The first 0.4 s, user input waits in the queue (no flash of a dialog for a short job, no
  // second command started meanwhile); after that the window-modal dialog takes the input.
  QTimer::singleShot(400, &loop, &QEventLoop::quit);
  if (!watcher.isFinished())
    loop.exec(QEventLoop::ExcludeUserInputEvents);
  if (!watcher.isFinished()) {
    dialog.show();
    loop.exec();
  }
  watcher.waitForFinished();
  if (failure)
    std::rethrow_exception(failure);
  return !cancelled;
}

} // namespace mocap::ui
