#include "job_progress_row.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>

#include <cmath>

namespace mocap::ui {

QString timeLeftText(double fraction, double elapsedSeconds)
{
  if (!(fraction >= 0.02) || fraction >= 1.0 || elapsedSeconds < 0.5)
    return {};
  const double left = elapsedSeconds * (1.0 - fraction) / fraction;
  if (left < 60.0)
    return JobProgressRow::tr("about %1 s left").arg(std::max(1, static_cast<int>(std::lround(left))));
  return JobProgressRow::tr("about %1 min left").arg(static_cast<int>(std::lround(left / 60.0)));
}

JobProgressRow::JobProgressRow(QWidget* parent) : QWidget(parent)
{
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  m_bar = new QProgressBar(this);
  m_bar->setRange(0, 1000);
  m_bar->setTextVisible(false);
  m_estimate = new QLabel(this);
  m_cancelButton = new QPushButton(tr("Cancel"), this);
  m_cancelButton->setToolTip(tr("Stop the computation (Esc)"));
  // Hidden between jobs, the bar and estimate keep their room: Cancel stays a button at the
  // right, and the dock does not jump when a preview starts.
  for (QWidget* part : {static_cast<QWidget*>(m_bar), static_cast<QWidget*>(m_estimate)}) {
    QSizePolicy policy = part->sizePolicy();
    policy.setRetainSizeWhenHidden(true);
    part->setSizePolicy(policy);
  }
  layout->addWidget(m_bar, 1);
  layout->addWidget(m_estimate);
  layout->addWidget(m_cancelButton);
  connect(m_cancelButton, &QPushButton::clicked, this, &JobProgressRow::cancel);
  finish();
}

JobControl JobProgressRow::begin()
{
  if (m_cancel)
    *m_cancel = true;  // an older job still running stops at its next checkpoint
  m_cancel = std::make_shared<std::atomic<bool>>(false);
  const unsigned job = ++m_job;
  m_clock.start();
  m_bar->setValue(0);
  m_bar->setRange(0, 0);  // busy until the first progress report
  m_estimate->clear();
  m_bar->setVisible(true);
  m_estimate->setVisible(true);
  m_cancelButton->setEnabled(true);
  QPointer<JobProgressRow> row(this);
  auto progress = [row, job](double fraction) {  // on the worker: post to the UI thread
    QMetaObject::invokeMethod(
        qApp, [row, job, fraction] {
          if (JobProgressRow* target = row.data())
            target->showProgress(job, fraction);
        },
        Qt::QueuedConnection);
  };
  return JobControl(std::move(progress), m_cancel);
}

void JobProgressRow::finish()
{
  m_cancel.reset();
  m_bar->setVisible(false);
  m_estimate->setVisible(false);
  m_cancelButton->setEnabled(false);
}

void JobProgressRow::cancel()
{
  if (m_cancel)
    *m_cancel = true;
  finish();
  emit cancelled();
}

void JobProgressRow::stopRunning()
{
  if (m_cancel)
    *m_cancel = true;
}

QString JobProgressRow::estimateText() const
{
  return m_estimate->text();
}

void JobProgressRow::showProgress(unsigned job, double fraction)
{
  if (job != m_job || !m_cancel)
    return;  // an older job's report, or after finish()
  m_bar->setRange(0, 1000);
  m_bar->setValue(static_cast<int>(std::lround(1000.0 * fraction)));
  m_estimate->setText(timeLeftText(fraction, static_cast<double>(m_clock.elapsed()) * 1e-3));
}

} // namespace mocap::ui
