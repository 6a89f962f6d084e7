#include "job_progress_row.h"

#include "document/job_runner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include <cmath>

namespace mocap::ui {

JobProgressRow::JobProgressRow(JobRunner& runner, QWidget* parent) : QWidget(parent)
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
  connect(m_cancelButton, &QPushButton::clicked, &runner, &JobRunner::cancel);
  connect(&runner, &JobRunner::started, this, &JobProgressRow::begin);
  connect(&runner, &JobRunner::progressed, this, &JobProgressRow::showProgress);
  connect(&runner, &JobRunner::cancelled, this, &JobProgressRow::finish);
  connect(&runner, &JobRunner::finished, this, &JobProgressRow::finish);
  if (runner.running())
    begin();
  else
    finish();
}

void JobProgressRow::begin()
{
  m_bar->setValue(0);
  m_bar->setRange(0, 0);  // busy until the first progress report
  m_estimate->clear();
  m_bar->setVisible(true);
  m_estimate->setVisible(true);
  m_cancelButton->setEnabled(true);
}

void JobProgressRow::finish()
{
  m_bar->setVisible(false);
  m_estimate->setVisible(false);
  m_cancelButton->setEnabled(false);
}

QString JobProgressRow::estimateText() const
{
  return m_estimate->text();
}

void JobProgressRow::showProgress(double fraction, const QString& timeLeft)
{
  if (!m_cancelButton->isEnabled())
    return;  // cancelled: the job is on its way out
  m_bar->setRange(0, 1000);
  m_bar->setValue(static_cast<int>(std::lround(1000.0 * fraction)));
  m_estimate->setText(timeLeft);
}

} // namespace mocap::ui
