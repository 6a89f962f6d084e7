#include "document/job_runner.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

QString timeLeftText(double fraction, double elapsedSeconds)
{
  if (!(fraction >= 0.02) || fraction >= 1.0 || elapsedSeconds < 0.5)
    return {};
  const double left = elapsedSeconds * (1.0 - fraction) / fraction;
  if (left < 60.0)
    return JobRunner::tr("about %1 s left").arg(std::max(1, static_cast<int>(std::lround(left))));
  return JobRunner::tr("about %1 min left").arg(static_cast<int>(std::lround(left / 60.0)));
}

JobRunner::JobRunner(QObject* parent) : QObject(parent) {}

JobRunner::~JobRunner()
{
  if (m_cancel)
    *m_cancel = true;
  for (QFuture<Outcome>& job : m_jobs)
    job.waitForFinished();
}

void JobRunner::launch(ErasedWork work)
{
  if (m_watcher) {  // superseded: it stops at its next checkpoint and is never delivered
    *m_cancel = true;
    m_watcher->disconnect(this);
    m_watcher->deleteLater();
  }
  m_jobs.erase(std::remove_if(m_jobs.begin(), m_jobs.end(), [](const QFuture<Outcome>& job) { return job.isFinished(); }),
               m_jobs.end());
  m_cancel = std::make_shared<std::atomic<bool>>(false);
  const unsigned job = ++m_job;
  m_fraction = 0.0;
  m_timeLeft.clear();
  m_clock.start();
  auto progress = [this, job](double fraction) {  // on the worker: post to this thread
    QMetaObject::invokeMethod(this, [this, job, fraction] { showProgress(job, fraction); }, Qt::QueuedConnection);
  };
  const JobControl control(std::move(progress), m_cancel);
  m_watcher = new QFutureWatcher<Outcome>(this);
  QFutureWatcher<Outcome>* watcher = m_watcher;
  connect(watcher, &QFutureWatcher<Outcome>::finished, this, [this, watcher] { onEnded(watcher); });
  m_jobs.push_back(QtConcurrent::run([work = std::move(work), control]() -> Outcome {
    try {
      return work(control);
    } catch (const JobCancelled&) {
      return {};
    } catch (const std::exception& e) {  // nothing may throw across the event loop
      return {{}, QString::fromStdString(e.what())};
    } catch (...) {
      return {{}, tr("unknown error")};
    }
  }));
  watcher->setFuture(m_jobs.back());
  emit started();
}

void JobRunner::cancel()
{
  if (!running() || cancelling())
    return;
  *m_cancel = true;
  emit cancelled();
}

void JobRunner::wait()
{
  if (!m_watcher)
    return;
  m_watcher->waitForFinished();
  onEnded(m_watcher);
}

void JobRunner::onEnded(QFutureWatcher<Outcome>* watcher)
{
  if (watcher != m_watcher)
    return;  // already handled by wait()
  Outcome outcome = watcher->result();
  watcher->disconnect(this);
  watcher->deleteLater();
  m_watcher = nullptr;
  if (outcome.deliver)
    outcome.deliver();
  else if (!outcome.error.isEmpty())
    emit failed(outcome.error);
  if (!running())  // a delivery may have started the next job
    emit finished();
}

void JobRunner::showProgress(unsigned job, double fraction)
{
  if (job != m_job || !running())
    return;  // an older job's report, or after it ended
  m_fraction = std::clamp(fraction, 0.0, 1.0);
  m_timeLeft = timeLeftText(m_fraction, static_cast<double>(m_clock.elapsed()) * 1e-3);
  emit progressed(m_fraction, m_timeLeft);
}

} // namespace mocap::ui
