#include "dialogs/job_dialog.h"

#include "document/job_runner.h"

#include <QEventLoop>
#include <QProgressDialog>
#include <QTimer>

#include <cmath>
#include <exception>
#include <limits>

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
  QProgressDialog dialog(label, QProgressDialog::tr("Cancel"), 0, 1000, parent);
  dialog.setWindowModality(Qt::WindowModal);
  dialog.setMinimumDuration(std::numeric_limits<int>::max());  // shown below, not by itself
  dialog.setAutoClose(false);
  dialog.setAutoReset(false);
  dialog.setValue(0);

  JobRunner runner;
  QObject::connect(&dialog, &QProgressDialog::canceled, &runner, &JobRunner::cancel);
  QObject::connect(&runner, &JobRunner::progressed, &dialog, [&dialog, label](double fraction, const QString& left) {
    if (dialog.wasCanceled())
      return;
    dialog.setValue(static_cast<int>(std::lround(1000.0 * fraction)));
    dialog.setLabelText(left.isEmpty() ? label : label + QLatin1Char('\n') + left);
  });
  bool done = false;
  std::exception_ptr failure;
  const RunningJob running;
  // `work` is the caller's and runs while this call waits: the runner's job refers to it. What it
  // throws is handed back as it is (the caller tells a read error from a bad file).
  runner.start(
      [&work](const JobControl& control) {
        try {
          work(control);
        } catch (const JobCancelled&) {
          throw;
        } catch (...) {
          return std::current_exception();
        }
        return std::exception_ptr{};
      },
      [&done, &failure](std::exception_ptr thrown) {
        done = true;
        failure = std::move(thrown);
      });
  QEventLoop loop;
  QObject::connect(&runner, &JobRunner::finished, &loop, &QEventLoop::quit);
  // The first 0.4 s, user input waits in the queue (no flash of a dialog for a short job, no
  // second command started meanwhile); after that the window-modal dialog takes the input.
  QTimer::singleShot(400, &loop, &QEventLoop::quit);
  if (runner.running())
    loop.exec(QEventLoop::ExcludeUserInputEvents);
  if (runner.running()) {
    dialog.show();
    loop.exec();
  }
  if (failure)
    std::rethrow_exception(failure);
  return done;
}

} // namespace mocap::ui
