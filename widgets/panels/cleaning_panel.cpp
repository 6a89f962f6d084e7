#include "panels/cleaning_panel.h"

#include "commands/apply_patches_command.h"
#include "commands/record_step_command.h"
#include "document/job_runner.h"
#include "document/take_document.h"
#include "panels/form_wrapping.h"
#include "panels/job_progress_row.h"

#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QTabWidget>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <utility>

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

/// A step's page in the tabs: it scrolls up and down inside its tab, so the preview options, the
/// progress, the status and Apply below the tabs stay in view whatever the dock's height (on a
/// 1600×1000 screen Apply sat below the fold of the whole panel's scroll area). It asks for the
/// step's width, so the dock's own scroll area still wraps or scrolls sideways as for any panel.
class CleaningStepPage final : public QScrollArea
{
public:
  CleaningStepPage(CleaningStep* step, QWidget* parent) : QScrollArea(parent)
  {
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setWidget(step);
  }

  [[nodiscard]] QSize minimumSizeHint() const override
  {
    return {stepWidth(), QScrollArea::minimumSizeHint().height()};
  }

  /// A low preferred height too: the dock's scroll area sizes a panel holding wrapped text by its
  /// preferred height for the width, which the whole step's height would push past the dock. The
  /// tabs take the panel's spare height anyway (stretch).
  [[nodiscard]] QSize sizeHint() const override { return {stepWidth(), 4 * fontMetrics().height()}; }

private:
  [[nodiscard]] int stepWidth() const
  {
    return widget()->minimumSizeHint().width() + verticalScrollBar()->sizeHint().width();
  }
};

/// The step on tab page `page`.
CleaningStep* stepOnPage(QWidget* page)
{
  const auto* scroll = qobject_cast<QScrollArea*>(page);
  return scroll ? qobject_cast<CleaningStep*>(scroll->widget()) : nullptr;
}

} // namespace

CleaningPanel::CleaningPanel(TakeDocument& document, QWidget* parent) : QWidget(parent), m_document(document)
{
  auto* layout = new QVBoxLayout(this);
  m_tabs = new QTabWidget(this);
  m_tabs->setUsesScrollButtons(true);  // in a dock narrower than the four tabs (a larger font, a translation)
  layout->addWidget(m_tabs, 1);
  m_live = new QCheckBox(tr("Live preview"), this);
  m_live->setObjectName(QStringLiteral("cleaningLivePreview"));
  m_live->setChecked(true);
  m_selectedOnly = new QCheckBox(tr("Selected markers only"), this);
  m_rangeOnly = new QCheckBox(tr("Selected frame range only"), this);
  m_rangeOnly->setObjectName(QStringLiteral("rangeOnly"));
  m_rangeOnly->setToolTip(tr("Change only the frames selected on the curves (Shift+drag)"));
  layout->addWidget(m_live);
  layout->addWidget(m_selectedOnly);
  layout->addWidget(m_rangeOnly);
  m_jobs = new JobRunner(this);
  layout->addWidget(new JobProgressRow(*m_jobs, this));
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  layout->addWidget(m_status);
  auto* buttons = new QHBoxLayout;
  m_apply = new QPushButton(tr("Apply"), this);
  m_apply->setObjectName(QStringLiteral("applyCleaning"));
  m_apply->setDefault(true);
  buttons->addStretch();
  buttons->addWidget(m_apply);
  layout->addLayout(buttons);

  m_debounce = new QTimer(this);
  m_debounce->setSingleShot(true);
  m_debounce->setInterval(200);
  connect(m_debounce, &QTimer::timeout, this, &CleaningPanel::start);
  connect(m_apply, &QPushButton::clicked, this, [this] { apply(); });
  connect(m_jobs, &JobRunner::cancelled, this, &CleaningPanel::cancel);
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

CleaningPanel::~CleaningPanel() = default;  // the runner stops and awaits its job

void CleaningPanel::addStep(CleaningStep* step)
{
  wrapLongFormRows(*step);  // a step may come after the panel is docked
  m_tabs->setTabToolTip(m_tabs->addTab(new CleaningStepPage(step, m_tabs), step->tabTitle()), step->title());
  connect(step, &CleaningStep::changed, this, &CleaningPanel::schedule);
}

void CleaningPanel::setCurrentStep(CleaningStep* step)
{
  for (int i = 0; i < m_tabs->count(); ++i)
    if (stepOnPage(m_tabs->widget(i)) == step)
      m_tabs->setCurrentIndex(i);
}

CleaningStep* CleaningPanel::currentStep() const
{
  return stepOnPage(m_tabs->currentWidget());
}

std::vector<CleaningStep*> CleaningPanel::steps() const
{
  std::vector<CleaningStep*> steps;
  for (int i = 0; i < m_tabs->count(); ++i)
    steps.push_back(stepOnPage(m_tabs->widget(i)));
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
  return m_jobs->running();
}

void CleaningPanel::schedule()
{
  if (!m_applying)
    m_applied.clear();  // a setting or the take changed: the next pass's preview speaks again
  ++m_generation;  // whatever is running or shown is stale now
  m_applyWhenReady = false;  // Apply applies what it was pressed for, not a later setting
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
  m_debounce->stop();
  CleaningStep* step = currentStep();
  if (!step || !m_document.hasTake())
    return;
  if (busy() && m_runningGeneration == m_generation)
    return;  // the newest request runs already
  m_runningGeneration = m_generation;
  if (m_applied.isEmpty())
    m_status->setText(tr("Computing…"));
  step->setScope(scope());
  // A newer request supersedes the running one: the runner stops it and never delivers it.
  m_jobs->start(
      [job = step->job(), take = m_document.take()](const JobControl& control) {
        try {
          return job(take, control);
        } catch (const JobCancelled&) {
          throw;
        } catch (const std::exception& e) {  // the step's own error is its summary
          StepResult failed;
          failed.summary = QString::fromStdString(e.what());
          return failed;
        }
      },
      [this, generation = m_generation](StepResult result) { onFinished(generation, std::move(result)); });
}

void CleaningPanel::onFinished(unsigned generation, StepResult result)
{
  if (generation != m_generation) {  // stale: the take or a setting changed while hidden or not live
    if (m_live->isChecked())
      m_debounce->start();
    return;
  }
  m_result = std::move(result);
  m_result.patches = onlySelected(std::move(m_result.patches));
  m_resultGeneration = generation;
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
  if (std::exchange(m_applyWhenReady, false))
    apply();
}

QString CleaningPanel::statusText() const
{
  return m_status->text();
}

void CleaningPanel::cancel()
{
  ++m_generation;
  m_applyWhenReady = false;
  m_debounce->stop();
  m_status->setText(tr("Cancelled"));
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
  if (m_resultGeneration != m_generation) {  // computed first; onFinished applies it
    start();
    m_applyWhenReady = busy();
    return 0;
  }
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
