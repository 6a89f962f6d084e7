#include "panels/cleaning_panel.h"

#include "commands/apply_patches_command.h"
#include "commands/record_step_command.h"
#include "document/take_document.h"
#include "panels/job_progress_row.h"

#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTabWidget>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace mocap::ui {

namespace {

/// The step's parameters as its form shows them (label → value), for the processing history:
/// what the user saw is what the history says, for every step without per-step code.
std::vector<std::pair<std::string, std::string>> shownParameters(const QWidget& step)
{
  std::vector<std::pair<std::string, std::string>> parameters;
  for (const QFormLayout* form : step.findChildren<QFormLayout*>()) {
    for (int row = 0; row < form->rowCount(); ++row) {
      const QLayoutItem* labelItem = form->itemAt(row, QFormLayout::LabelRole);
      const QLayoutItem* fieldItem = form->itemAt(row, QFormLayout::FieldRole);
      const auto* label = labelItem ? qobject_cast<const QLabel*>(labelItem->widget()) : nullptr;
      QWidget* field = fieldItem ? fieldItem->widget() : nullptr;
      if (!field || !field->isEnabled())
        continue;
      QString value;
      if (const auto* combo = qobject_cast<const QComboBox*>(field))
        value = combo->currentText();
      else if (const auto* spin = qobject_cast<const QAbstractSpinBox*>(field))
        value = spin->text();
      else if (const auto* box = qobject_cast<const QCheckBox*>(field))
        value = box->isChecked() ? QStringLiteral("on") : QStringLiteral("off");
      else
        continue;
      const auto* check = qobject_cast<const QCheckBox*>(field);
      QString name = label ? label->text() : check ? check->text() : QString();
      name.remove(QLatin1Char('&'));
      if (!name.isEmpty())
        parameters.emplace_back(name.trimmed().toStdString(), value.trimmed().toStdString());
    }
  }
  return parameters;
}

} // namespace

CleaningPanel::CleaningPanel(TakeDocument& document, QWidget* parent) : QWidget(parent), m_document(document)
{
  auto* layout = new QVBoxLayout(this);
  m_tabs = new QTabWidget(this);
  layout->addWidget(m_tabs, 1);
  m_live = new QCheckBox(tr("Live preview"), this);
  m_live->setChecked(true);
  m_selectedOnly = new QCheckBox(tr("Selected markers only"), this);
  m_rangeOnly = new QCheckBox(tr("Selected frame range only"), this);
  m_rangeOnly->setObjectName(QStringLiteral("rangeOnly"));
  m_rangeOnly->setToolTip(tr("Change only the frames selected on the curves (Shift+drag)"));
  layout->addWidget(m_live);
  layout->addWidget(m_selectedOnly);
  layout->addWidget(m_rangeOnly);
  m_progress = new JobProgressRow(this);
  layout->addWidget(m_progress);
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  layout->addWidget(m_status);
  auto* buttons = new QHBoxLayout;
  m_apply = new QPushButton(tr("Apply"), this);
  m_apply->setDefault(true);
  buttons->addStretch();
  buttons->addWidget(m_apply);
  layout->addLayout(buttons);

  m_debounce = new QTimer(this);
  m_debounce->setSingleShot(true);
  m_debounce->setInterval(200);
  connect(m_debounce, &QTimer::timeout, this, &CleaningPanel::start);
  connect(&m_watcher, &QFutureWatcher<StepResult>::finished, this, &CleaningPanel::onFinished);
  connect(m_apply, &QPushButton::clicked, this, [this] { apply(); });
  connect(m_progress, &JobProgressRow::cancelled, this, &CleaningPanel::cancel);
  connect(m_live, &QCheckBox::toggled, this, [this](bool on) {
    if (on)
      schedule();
    else
      m_document.clearPreview();
  });
  connect(m_selectedOnly, &QCheckBox::toggled, this, &CleaningPanel::schedule);
  connect(m_rangeOnly, &QCheckBox::toggled, this, &CleaningPanel::schedule);
  connect(&document, &TakeDocument::rangeChanged, this, [this] {
    if (m_rangeOnly->isChecked())
      schedule();
  });
  connect(m_tabs, &QTabWidget::currentChanged, this, &CleaningPanel::schedule);
  connect(&document, &TakeDocument::takeReset, this, &CleaningPanel::schedule);
  connect(&document, &TakeDocument::samplesChanged, this, &CleaningPanel::schedule);
  connect(&document, &TakeDocument::markersChanged, this, &CleaningPanel::schedule);
  connect(&document, &TakeDocument::selectionChanged, this, [this] {
    if (m_selectedOnly->isChecked())
      schedule();
  });
}

CleaningPanel::~CleaningPanel()
{
  m_watcher.waitForFinished();  // the job holds its own take copy; just let it end
}

void CleaningPanel::addStep(CleaningStep* step)
{
  m_tabs->addTab(step, step->title());
  connect(step, &CleaningStep::changed, this, &CleaningPanel::schedule);
}

void CleaningPanel::setCurrentStep(CleaningStep* step)
{
  m_tabs->setCurrentWidget(step);
}

CleaningStep* CleaningPanel::currentStep() const
{
  return qobject_cast<CleaningStep*>(m_tabs->currentWidget());
}

std::vector<CleaningStep*> CleaningPanel::steps() const
{
  std::vector<CleaningStep*> steps;
  for (int i = 0; i < m_tabs->count(); ++i)
    steps.push_back(static_cast<CleaningStep*>(m_tabs->widget(i)));
  return steps;
}

CleanOptions CleaningPanel::cleanOptions() const
{
  CleanOptions options;
  options.spikes.reset();  // each step the panel has turns its part on
  options.fill.reset();
  options.smooth.reset();
  for (const CleaningStep* step : steps())
    step->addToPreset(options);
  return options;
}

QStringList CleaningPanel::loadCleanOptions(const CleanOptions& options)
{
  QStringList off;
  for (CleaningStep* step : steps())
    if (!step->loadPreset(options))
      off << step->title();
  return off;
}

bool CleaningPanel::busy() const
{
  return m_watcher.isRunning();
}

void CleaningPanel::schedule()
{
  if (!m_applying)
    m_applied.clear();  // a setting or the take changed: the next pass's preview speaks again
  ++m_generation;  // whatever is running or shown is stale now
  if (m_live->isChecked() && isVisible())
    m_debounce->start();
}

void CleaningPanel::showEvent(QShowEvent* event)
{
  QWidget::showEvent(event);
  if (m_resultGeneration != m_generation)
    schedule();  // requests made while hidden were deferred
}

void CleaningPanel::refresh()
{
  ++m_generation;
  start();
}

void CleaningPanel::start()
{
  CleaningStep* step = currentStep();
  if (!step || !m_document.hasTake())
    return;
  if (m_watcher.isRunning()) {
    if (m_runningGeneration != m_generation)
      m_progress->stopRunning();  // superseded: stop it at its next checkpoint
    m_debounce->start();  // one job at a time; try again when this one ends
    return;
  }
  m_runningGeneration = m_generation;
  const JobControl control = m_progress->begin();
  if (m_applied.isEmpty())
    m_status->setText(tr("Computing…"));
  step->setScope(scope());
  m_watcher.setFuture(QtConcurrent::run([job = step->job(), take = m_document.take(), control] {
    try {
      return job(take, control);
    } catch (const JobCancelled&) {
      return StepResult{};  // dropped: its generation is stale
    } catch (const std::exception& e) {  // nothing may throw across the event loop
      StepResult failed;
      failed.summary = QString::fromStdString(e.what());
      return failed;
    }
  }));
}

void CleaningPanel::onFinished()
{
  m_progress->finish();
  if (m_runningGeneration != m_generation) {  // superseded or cancelled
    if (m_live->isChecked())
      m_debounce->start();
    return;
  }
  m_result = m_watcher.result();
  m_result.patches = onlySelected(std::move(m_result.patches));
  m_resultGeneration = m_runningGeneration;
  int samples = 0;
  for (const SamplePatch& p : m_result.patches)
    samples += static_cast<int>(p.size());
  const QString preview = tr("%1 — %n sample(s) would change", nullptr, samples).arg(m_result.summary);
  if (m_applied.isEmpty())
    m_status->setText(preview);
  else  // what was done stays first; a next pass that would change more follows
    m_status->setText(samples == 0 ? m_applied : m_applied + QLatin1Char('\n') + tr("Next pass: %1").arg(preview));
  if (CleaningStep* step = currentStep())
    step->showResult(m_result);
  if (m_result.detection)  // flags are the last detection's, on every tab, until the next one
    m_document.setFlags(m_result.flags);
  m_document.setPreview(m_result.patches);
}

QString CleaningPanel::statusText() const
{
  return m_status->text();
}

void CleaningPanel::cancel()
{
  ++m_generation;
  m_debounce->stop();
  m_status->setText(tr("Cancelled"));
}

void CleaningPanel::waitForPreview()
{
  m_debounce->stop();
  if (!m_watcher.isRunning() && m_resultGeneration != m_generation)
    start();
  while (m_watcher.isRunning() || m_resultGeneration != m_generation) {
    m_watcher.waitForFinished();
    QCoreApplication::processEvents();
    if (!m_watcher.isRunning() && m_resultGeneration != m_generation)
      start();
  }
}

StepScope CleaningPanel::scope() const
{
  StepScope scope;
  scope.markersOnly = m_selectedOnly->isChecked();
  if (scope.markersOnly)
    scope.markers = m_document.selection();  // sorted by the document
  scope.rangeOnly = m_rangeOnly->isChecked();
  scope.first = m_document.rangeFirst();
  scope.last = m_document.rangeLast();
  return scope;
}

void CleaningPanel::dropRepairedFlags(const std::vector<SamplePatch>& repairs)
{
  // The flags the repair replaces are settled; the others (unchecked, out of scope) stay.
  // O(#flags · log #repaired).
  std::vector<std::pair<Eigen::Index, Eigen::Index>> repaired;
  for (const SamplePatch& patch : repairs)
    for (Eigen::Index frame : patch.frames)
      repaired.emplace_back(patch.marker, frame);
  std::sort(repaired.begin(), repaired.end());
  std::vector<std::pair<Eigen::Index, Eigen::Index>> flags = m_document.flags();
  const auto isRepaired = [&](const auto& flag) { return std::binary_search(repaired.begin(), repaired.end(), flag); };
  flags.erase(std::remove_if(flags.begin(), flags.end(), isRepaired), flags.end());
  if (flags.size() != m_document.flags().size())
    m_document.setFlags(std::move(flags));
}

std::vector<SamplePatch> CleaningPanel::onlySelected(std::vector<SamplePatch> patches) const
{
  if (const CleaningStep* step = currentStep(); step && step->wholeTake())
    return patches;  // all markers, all frames, or nothing
  if (m_rangeOnly->isChecked()) {
    // No range selected: nothing to change rather than everything.
    for (SamplePatch& patch : patches)
      patch = patchWithin(patch, m_document.rangeFirst(), m_document.rangeLast());
  }
  const auto& selection = m_document.selection();
  const bool markersOnly = m_selectedOnly->isChecked();
  patches.erase(std::remove_if(patches.begin(), patches.end(),
                               [&](const SamplePatch& p) {
                                 return p.empty() || (markersOnly && !std::binary_search(selection.begin(),
                                                                                         selection.end(), p.marker));
                               }),
                patches.end());
  return patches;
}

int CleaningPanel::apply()
{
  CleaningStep* step = currentStep();
  if (!step || !m_document.hasTake())
    return 0;
  if (m_resultGeneration != m_generation)
    waitForPreview();
  step->setScope(scope());
  std::vector<SamplePatch> patches = onlySelected(step->patchesToApply(m_document.take(), m_result));
  int samples = 0;
  for (const SamplePatch& p : patches)
    samples += static_cast<int>(p.size());
  m_document.clearPreview();
  if (m_result.detection)
    dropRepairedFlags(patches);
  if (samples == 0) {
    m_status->setText(tr("Nothing to apply"));
    return 0;
  }
  step->applied(patches);
  const QString done = tr("Applied: %1").arg(step->appliedSummary(patches, m_result));
  m_applying = true;
  m_document.undoStack()->push(makeRecordedEdit(m_document, std::move(patches), step->title(),
                                                step->title().toStdString(), shownParameters(*step)));
  m_applying = false;
  m_applied = done;
  m_status->setText(m_applied);
  return samples;
}

} // namespace mocap::ui
