#include "panels/layout_planning_panel.h"

#include "document/bound_rig.h"
#include "document/job_runner.h"
#include "document/layout_plan_model.h"
#include "document/session_option.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "panels/job_progress_row.h"
#include "panels/reference_markers_row.h"
#include "views/layout_error_plot.h"

#include "mocap/base/file_io.h"
#include "mocap/model/marker_edits.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/marker_set.h"
#include "mocap/io/marker_set_io.h"
#include "mocap/io/take_io.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

namespace {

const QString kGroup = QStringLiteral("layoutPlanning/");

QString settingKey(const char* name)
{
  return kGroup + QLatin1String(name);
}

/// The panel's remembered settings, typed ("layoutPlanning/…"; the defaults are LayoutPlanParameters').
struct LayoutPlanningSettings
{
  SessionOption<QString> method{settingKey("method"), QString()};  // selectionMethodName; empty: the default
  SessionOption<double> variance{settingKey("variance"), LayoutPlanParameters{}.variance};
  SessionOption<int> restarts{settingKey("restarts"), LayoutPlanParameters{}.restarts};
  SessionOption<int> minK{settingKey("minK"), LayoutPlanParameters{}.minK};
  SessionOption<int> maxK{settingKey("maxK"), LayoutPlanParameters{}.maxK};
  SessionOption<int> seed{settingKey("seed"), LayoutPlanParameters{}.seed};
  SessionOption<int> randomSubsets{settingKey("randomSubsets"), LayoutPlanParameters{}.randomSubsets};
  SessionOption<QString> keyPoses{settingKey("keyPoses"), QString()};
  SessionOption<QString> pairsFile{settingKey("pairsFile"), QString()};
  SessionOption<QStringList> markers{settingKey("markers"), QStringList()};
  SessionOption<QStringList> exclude{settingKey("exclude"), QStringList()};
  SessionOption<QStringList> extraTakes{settingKey("extraTakes"), QStringList()};
  SessionOption<bool> judgeOnRig{settingKey("judgeOnRig"), false};
  SessionOption<QString> exportFolder{settingKey("exportFolder"), QString()};  // empty: the take's folder
};

std::vector<std::string> toStd(const QStringList& list)
{
  std::vector<std::string> result;
  for (const QString& s : list)
    result.push_back(s.toStdString());
  return result;
}

QStringList splitLabels(const QString& text)
{
  QStringList labels;
  for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts))
    if (const QString label = part.trimmed(); !label.isEmpty())
      labels << label;
  return labels;
}

// The worker: the open take (a copy) and the extra take files, planned as `mocap pfa` plans them.
// Never throws: a failure is the result's error.
std::shared_ptr<LayoutPlanResult> planInBackground(Take openTake, const QStringList& extraTakes,
                                                   const LayoutRequest& request, const BoundRig& rig,
                                                   const JobControl& control)
{
  auto result = std::make_shared<LayoutPlanResult>();
  try {
    std::vector<Take> takes;
    takes.push_back(std::move(openTake));
    for (const QString& path : extraTakes)
      takes.push_back(readTake(path.toStdString()));
    // With a rig, planning takes the first 60 % of the bar and judging the layouts the rest.
    const double planShare = rig.rig ? 0.6 : 1.0;
    static_cast<LayoutResult&>(*result) = planLayout(takes, request, control.part(0.0, planShare));
    if (rig.rig && !result->plan.cancelled) {
      try {
        LayoutRigErrorOptions options;
        options.randomSubsets = request.plan.randomSubsets;
        options.seed = request.plan.pfa.seed;
        result->rig = planRigErrors(takes, *result, *rig.rig, rig.binding, options, control.part(planShare, 1.0));
      } catch (const std::exception& e) {  // the plan stands without the rig measure
        result->rigError = QString::fromStdString(e.what());
      }
    }
    result->pairSource = request.pairsFile.empty()
                             ? QCoreApplication::translate("mocap::ui::LayoutPlanningPanel", "detected")
                             : QFileInfo(QString::fromStdString(request.pairsFile)).fileName();
  } catch (const std::exception& e) {  // nothing may throw across the event loop
    result->error = QString::fromStdString(e.what());
  }
  return result;
}

} // namespace

LayoutRequest layoutRequest(const LayoutPlanParameters& parameters, const std::vector<std::string>& referenceLabels)
{
  LayoutRequest request;
  request.stabilizeLabels = referenceLabels;
  request.markerPatterns = toStd(parameters.markerPatterns);
  request.excludePatterns = toStd(parameters.excludePatterns);
  request.keyPoses = parseKeyPoses(parameters.keyPoses.toStdString());
  request.pairsFile = parameters.pairsFile.toStdString();
  request.plan.method = parameters.method;
  request.plan.pfa.varianceFraction = parameters.variance;
  request.plan.pfa.restarts = parameters.restarts;
  request.plan.pfa.minK = parameters.minK;
  request.plan.pfa.maxK = parameters.maxK;
  request.plan.pfa.seed = static_cast<std::uint64_t>(parameters.seed);
  request.plan.randomSubsets = parameters.randomSubsets;
  return request;
}

LayoutPlanningPanel::LayoutPlanningPanel(StudioSession& session, QWidget* parent)
    : QWidget(parent),
      m_session(session),
      m_document(session.document()),
      m_plan(session.layoutPlan()),
      m_jobs(new JobRunner(this))
{
  buildForm();
  readSettings();
  connect(m_plot, &LayoutErrorPlot::sizeSelected, &m_plan, &LayoutPlanModel::setSelectedSize);
  connect(&m_plan, &LayoutPlanModel::changed, this, &LayoutPlanningPanel::followPlan);
  setIdle(true);
  followPlan();  // a plan the session already holds
}

LayoutPlanningPanel::~LayoutPlanningPanel() = default;  // the runner stops and awaits its job

void LayoutPlanningPanel::buildForm()
{
  // Everything scrolls, so the dock never forces the window taller than its own minimum.
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  auto* content = new QWidget(scroll);
  scroll->setWidget(content);
  outer->addWidget(scroll);
  auto* layout = new QVBoxLayout(content);
  auto* form = new QFormLayout;
  form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);

  m_takes = new QListWidget(this);
  m_takes->setToolTip(tr("Take files planned together with the open take (they must have its markers)"));
  m_takes->setMaximumHeight(56);
  m_addTake = new QPushButton(tr("Add…"), this);
  m_removeTake = new QPushButton(tr("Remove"), this);
  auto* takeButtons = new QVBoxLayout;
  takeButtons->addWidget(m_addTake);
  takeButtons->addWidget(m_removeTake);
  takeButtons->addStretch();
  auto* takeRow = new QHBoxLayout;
  takeRow->addWidget(m_takes, 1);
  takeRow->addLayout(takeButtons);
  form->addRow(tr("More takes:"), takeRow);
  connect(m_addTake, &QPushButton::clicked, this, [this] {
    const QStringList paths = QFileDialog::getOpenFileNames(this, tr("Add takes"), QFileInfo(m_document.filePath()).absolutePath(),
                                                            tr("Motion capture (*.c3d *.trc);;All files (*)"));
    for (const QString& path : paths)
      if (m_takes->findItems(path, Qt::MatchExactly).isEmpty())
        m_takes->addItem(path);
  });
  connect(m_removeTake, &QPushButton::clicked, this, [this] { qDeleteAll(m_takes->selectedItems()); });
  m_takes->setSelectionMode(QAbstractItemView::ExtendedSelection);

  m_method = new QComboBox(this);
  m_method->addItem(tr("PFA (principal feature analysis)"), static_cast<int>(SelectionMethod::Pfa));
  m_method->addItem(tr("Greedy (least reconstruction error)"), static_cast<int>(SelectionMethod::Greedy));
  m_method->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);  // the dock stays narrow
  m_method->setMinimumContentsLength(18);
  form->addRow(tr("Method:"), m_method);

  m_variance = new QDoubleSpinBox(this);
  m_variance->setRange(0.5, 1.0);
  m_variance->setDecimals(3);
  m_variance->setSingleStep(0.01);
  m_variance->setToolTip(tr("Share of the motion's variance the PCA keeps (the paper: 0.98)"));
  form->addRow(tr("Variance kept:"), m_variance);

  m_restarts = new QSpinBox(this);
  m_restarts->setRange(1, 100000);
  m_restarts->setToolTip(tr("k-means restarts per cluster count (the paper: 1000; fewer run faster)"));
  form->addRow(tr("Restarts:"), m_restarts);

  m_minK = new QSpinBox(this);
  m_maxK = new QSpinBox(this);
  for (QSpinBox* k : {m_minK, m_maxK}) {
    k->setRange(0, 10000);
    k->setSpecialValueText(tr("all"));
  }
  auto* kRow = new QHBoxLayout;
  kRow->addWidget(m_minK, 1);
  kRow->addWidget(new QLabel(tr("to"), this));
  kRow->addWidget(m_maxK, 1);
  form->addRow(tr("Clusters k:"), kRow);

  m_seed = new QSpinBox(this);
  m_seed->setRange(0, 2147483647);
  form->addRow(tr("Seed:"), m_seed);

  m_randomSubsets = new QSpinBox(this);
  m_randomSubsets->setRange(0, 100000);
  m_randomSubsets->setSpecialValueText(tr("none"));
  m_randomSubsets->setToolTip(tr("Random marker sets scored at every size, the baseline a plan must beat"));
  form->addRow(tr("Random sets:"), m_randomSubsets);

  m_keyPoses = new QLineEdit(this);
  m_keyPoses->setPlaceholderText(tr("automatic"));
  m_keyPoses->setToolTip(tr("Key poses of the blendshape basis: frame numbers, comma-separated (TAKE:FRAME for a "
                            "further take, TAKE from 1); blank: the most extreme frames"));
  form->addRow(tr("Key poses:"), m_keyPoses);

  m_pairs = new QLineEdit(this);
  m_pairs->setPlaceholderText(tr("detected automatically"));
  m_pairs->setToolTip(tr("Mirror pairs: a text file (two labels a line) or a marker-set file (.json)"));
  auto* browsePairs = new QPushButton(tr("…"), this);
  browsePairs->setToolTip(tr("Choose a pairs file"));
  auto* pairsRow = new QHBoxLayout;
  pairsRow->addWidget(m_pairs, 1);
  pairsRow->addWidget(browsePairs);
  form->addRow(tr("Pairs file:"), pairsRow);
  connect(browsePairs, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Pairs file"), m_pairs->text(),
                                                      tr("Pairs (*.txt *.json);;All files (*)"));
    if (!path.isEmpty())
      m_pairs->setText(path);
  });

  m_reference = new ReferenceMarkersRow(
      m_document, tr("Head motion is removed with these markers before planning, and they are not planned over "
                     "(a reduced capture still needs them)."),
      this);
  connect(m_reference, &ReferenceMarkersRow::editRequested, this,
          &LayoutPlanningPanel::editReferenceMarkersRequested);
  form->addRow(tr("Reference markers:"), m_reference);

  m_markerPatterns = new QLineEdit(this);
  m_markerPatterns->setPlaceholderText(tr("all but the reference markers"));
  m_markerPatterns->setToolTip(tr("Markers to plan over, comma-separated; * and ? match any run and any character "
                                  "(e.g. section1-*, lip?)"));
  form->addRow(tr("Plan markers:"), m_markerPatterns);

  m_exclude = new QLineEdit(this);
  m_exclude->setPlaceholderText(tr("none"));
  m_exclude->setToolTip(tr("Markers left out of the plan, comma-separated; * and ? match any run and any character "
                           "(unlabelled points and the reference markers always are)"));
  form->addRow(tr("Leave out:"), m_exclude);
  m_judgeOnRig = new QCheckBox(tr("Judge layouts on the blendshape rig"), this);
  m_judgeOnRig->setToolTip(tr("Also solve the loaded rig's weights from each layout and from every bound marker, "
                              "and plot their MSE (the seed paper's measure on a semantic rig; mocap pfa --rig)"));
  connect(m_judgeOnRig, &QCheckBox::toggled, this, [this] { writeSettings(); });
  form->addRow(m_judgeOnRig);
  layout->addLayout(form);

  auto* runRow = new QHBoxLayout;
  m_run = new QPushButton(tr("Run"), this);
  m_run->setDefault(true);
  runRow->addWidget(m_run);
  runRow->addWidget(new JobProgressRow(*m_jobs, this), 1);  // bar, time left, Cancel
  layout->addLayout(runRow);
  connect(m_run, &QPushButton::clicked, this, [this] { run(); });
  connect(m_jobs, &JobRunner::cancelled, this, [this] { m_status->setText(tr("Cancelling…")); });

  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(m_status);

  auto* splitter = new QSplitter(Qt::Vertical, this);
  m_plot = new LayoutErrorPlot(splitter);
  m_markers = new QTableWidget(0, 3, splitter);
  m_markers->setHorizontalHeaderLabels({tr("Marker"), tr("Mirror"), tr("Pair frequency")});
  m_markers->horizontalHeader()->setStretchLastSection(true);
  m_markers->verticalHeader()->hide();
  m_markers->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_markers->setToolTip(tr("The selected layout's markers; the frequency is the share of k-means restarts "
                           "that chose the marker's pair (PFA only)"));
  auto* plotBox = new QWidget(splitter);
  auto* plotLayout = new QVBoxLayout(plotBox);
  plotLayout->setContentsMargins(0, 0, 0, 0);
  m_plot->setParent(plotBox);
  plotLayout->addWidget(m_plot, 1);
  m_rigSummary = new QLabel(plotBox);
  m_rigSummary->setWordWrap(true);
  m_rigSummary->hide();
  plotLayout->addWidget(m_rigSummary);
  splitter->addWidget(plotBox);
  splitter->addWidget(m_markers);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 2);
  layout->addWidget(splitter, 1);

  auto* exportRow = new QHBoxLayout;
  m_exportLabels = new QPushButton(tr("Export Labels…"), this);
  m_exportSet = new QPushButton(tr("Export Marker Set…"), this);
  m_exportTake = new QPushButton(tr("Export Take…"), this);
  exportRow->addWidget(m_exportLabels);
  exportRow->addWidget(m_exportSet);
  exportRow->addWidget(m_exportTake);
  layout->addLayout(exportRow);
  connect(m_exportLabels, &QPushButton::clicked, this, [this] {
    exportWithDialog(tr("Export marker labels"), tr("Label list (*.txt)"), &LayoutPlanningPanel::exportLabelList);
  });
  connect(m_exportSet, &QPushButton::clicked, this, [this] {
    exportWithDialog(tr("Export marker set"), tr("Marker set (*.json)"), &LayoutPlanningPanel::exportMarkerSet);
  });
  connect(m_exportTake, &QPushButton::clicked, this, [this] {
    exportWithDialog(tr("Export reduced take"), tr("C3D (*.c3d);;TRC (*.trc)"), &LayoutPlanningPanel::exportTake);
  });
}

LayoutPlanParameters LayoutPlanningPanel::parameters() const
{
  LayoutPlanParameters p;
  for (int i = 0; i < m_takes->count(); ++i)
    p.extraTakes << m_takes->item(i)->text();
  p.method = static_cast<SelectionMethod>(m_method->currentData().toInt());
  p.variance = m_variance->value();
  p.restarts = m_restarts->value();
  p.minK = m_minK->value();
  p.maxK = m_maxK->value();
  p.seed = m_seed->value();
  p.randomSubsets = m_randomSubsets->value();
  p.keyPoses = m_keyPoses->text().trimmed();
  p.pairsFile = m_pairs->text().trimmed();
  p.markerPatterns = splitLabels(m_markerPatterns->text());
  p.excludePatterns = splitLabels(m_exclude->text());
  return p;
}

void LayoutPlanningPanel::setParameters(const LayoutPlanParameters& p)
{
  m_takes->clear();
  m_takes->addItems(p.extraTakes);
  m_method->setCurrentIndex(std::max(0, m_method->findData(static_cast<int>(p.method))));
  m_variance->setValue(p.variance);
  m_restarts->setValue(p.restarts);
  m_minK->setValue(p.minK);
  m_maxK->setValue(p.maxK);
  m_seed->setValue(p.seed);
  m_randomSubsets->setValue(p.randomSubsets);
  m_keyPoses->setText(p.keyPoses);
  m_pairs->setText(p.pairsFile);
  m_markerPatterns->setText(p.markerPatterns.join(QStringLiteral(", ")));
  m_exclude->setText(p.excludePatterns.join(QStringLiteral(", ")));
}

void LayoutPlanningPanel::readSettings()
{
  const LayoutPlanningSettings settings;
  LayoutPlanParameters p;  // the defaults
  p.method = parseSelectionMethod(settings.method.get().toStdString()).value_or(p.method);
  p.variance = settings.variance;
  p.restarts = settings.restarts;
  p.minK = settings.minK;
  p.maxK = settings.maxK;
  p.seed = settings.seed;
  p.randomSubsets = settings.randomSubsets;
  p.keyPoses = settings.keyPoses;
  p.pairsFile = settings.pairsFile;
  p.markerPatterns = settings.markers;
  p.excludePatterns = settings.exclude;
  p.extraTakes = settings.extraTakes;
  setParameters(p);
  const QSignalBlocker blocker(m_judgeOnRig);
  m_judgeOnRig->setChecked(settings.judgeOnRig);
}

void LayoutPlanningPanel::setJudgeOnRig(bool on)
{
  m_judgeOnRig->setChecked(on);
}

void LayoutPlanningPanel::writeSettings() const
{
  LayoutPlanningSettings settings;
  const LayoutPlanParameters p = parameters();
  const std::string_view method = selectionMethodName(p.method);
  settings.method = QString::fromUtf8(method.data(), static_cast<qsizetype>(method.size()));
  settings.variance = p.variance;
  settings.restarts = p.restarts;
  settings.minK = p.minK;
  settings.maxK = p.maxK;
  settings.seed = p.seed;
  settings.randomSubsets = p.randomSubsets;
  settings.keyPoses = p.keyPoses;
  settings.pairsFile = p.pairsFile;
  settings.markers = p.markerPatterns;
  settings.exclude = p.excludePatterns;
  settings.extraTakes = p.extraTakes;
  settings.judgeOnRig = m_judgeOnRig->isChecked();
}

QString LayoutPlanningPanel::run()
{
  if (busy())
    return tr("A plan is already running.");
  const LayoutPlanParameters p = parameters();
  QString problem;
  if (!m_document.hasTake())
    problem = tr("Open a take first.");
  else if (p.minK > 0 && p.maxK > 0 && p.minK > p.maxK)
    problem = tr("The smallest cluster count (%1) is larger than the largest (%2).").arg(p.minK).arg(p.maxK);
  else if (!p.pairsFile.isEmpty() && !QFileInfo(p.pairsFile).isFile())
    problem = tr("The pairs file %1 does not exist.").arg(p.pairsFile);
  const std::vector<std::string> reference = m_document.referenceLabels();
  if (problem.isEmpty() && !reference.empty() && reference.size() < 3)
    problem = tr("Head motion needs at least three reference markers (Marker ▸ Reference Markers…).");
  LayoutRequest request;
  if (problem.isEmpty())
    problem = checkedRequest(p, reference, request);
  BoundRig rig;
  if (problem.isEmpty() && m_judgeOnRig->isChecked()) {
    rig = m_session.boundRig();
    if (!rig.rig || rig.binding.markers.empty())
      problem = tr("Judging on the rig needs a blendshape rig (Blendshape Solve panel) and the markers bound to its "
                   "neutral (Face Mesh panel); or switch it off.");
  }
  if (!problem.isEmpty()) {
    showError(problem);
    return problem;
  }
  writeSettings();
  m_status->setStyleSheet({});
  m_status->setToolTip({});
  m_status->setText(tr("Planning…"));
  setIdle(false);
  m_jobs->start(
      [take = m_document.take(), extraTakes = p.extraTakes, request = std::move(request),
       rig = std::move(rig)](const JobControl& control) mutable {
        return planInBackground(std::move(take), extraTakes, request, rig, control);
      },
      [this](std::shared_ptr<LayoutPlanResult> result) { onFinished(std::move(result)); });
  return {};
}

QString LayoutPlanningPanel::checkedRequest(const LayoutPlanParameters& parameters,
                                            const std::vector<std::string>& reference, LayoutRequest& request) const
{
  using Field = LayoutRequestError::Field;
  const auto fieldName = [](Field field) {
    return field == Field::KeyPoses ? tr("Key poses") : field == Field::Markers ? tr("Plan markers") : tr("Leave out");
  };
  try {
    request = layoutRequest(parameters, reference);
    // The patterns are checked here too, so a typo is answered at once rather than after the take files are read.
    const std::vector<std::string>& labels = m_document.take().labels();
    if (!request.markerPatterns.empty())  // as planLayout: model outputs are never planned
      (void)labelsMatching(markerLabels(m_document.take()), request.markerPatterns, Field::Markers);
    if (!request.excludePatterns.empty())
      (void)labelsMatching(labels, request.excludePatterns, Field::Exclude);
  } catch (const LayoutRequestError& e) {
    return tr("%1: %2").arg(fieldName(e.field()), QString::fromStdString(e.what()));
  }
  return {};
}

void LayoutPlanningPanel::cancel()
{
  m_jobs->cancel();
}

bool LayoutPlanningPanel::busy() const
{
  return m_jobs->running();
}

void LayoutPlanningPanel::setIdle(bool idle)
{
  m_idle = idle;
  m_run->setEnabled(idle);
  const bool exportable = idle && !m_plan.selectedLabels().empty();
  m_exportLabels->setEnabled(exportable);
  m_exportSet->setEnabled(exportable);
  m_exportTake->setEnabled(exportable);
  for (QWidget* w : std::initializer_list<QWidget*>{m_takes, m_addTake, m_removeTake, m_method, m_variance,
                                                    m_restarts, m_minK, m_maxK, m_seed, m_randomSubsets,
                                                    m_keyPoses, m_pairs, m_reference, m_markerPatterns,
                                                    m_exclude})
    w->setEnabled(idle);
}

void LayoutPlanningPanel::showError(const QString& message)
{
  m_status->setStyleSheet(QStringLiteral("color: #c0392b;"));
  m_status->setText(message);
}

QString LayoutPlanningPanel::statusText() const
{
  return m_status->text();
}

void LayoutPlanningPanel::onFinished(std::shared_ptr<LayoutPlanResult> result)
{
  if (!result->error.isEmpty()) {
    showError(tr("Planning failed: %1").arg(result->error));
  } else if (result->plan.cancelled) {
    m_status->setText(tr("Cancelled; the previous result is kept."));
  } else {
    showResult(result);
    const Eigen::Index size = m_plot->selectedSize();  // the recommended one
    m_plan.setResult(std::move(result), size);          // the table and highlight follow
  }
  setIdle(true);
}

void LayoutPlanningPanel::showResult(std::shared_ptr<const LayoutPlanResult> result)
{
  m_shown = std::move(result);
  if (!m_shown) {
    m_plot->clear();
    return;
  }
  const LayoutPlan& plan = m_shown->plan;
  const LayoutFrames& frames = m_shown->frames;
  m_status->setStyleSheet({});
  m_status->setText(tr("%1 markers, %2 frames (%7), %3 pairs (%4), %5 PCA components. Recommended: %6 markers.")
                        .arg(frames.markerCount())
                        .arg(static_cast<qlonglong>(frames.frames.rows()))
                        .arg(m_shown->symmetry.pairs().size())
                        .arg(m_shown->pairSource)
                        .arg(static_cast<qlonglong>(plan.pcaComponents))
                        .arg(static_cast<qlonglong>(plan.recommendedSize))
                        .arg(frames.stabilized ? tr("head motion removed with %n reference marker(s)", nullptr,
                                                    static_cast<int>(m_shown->stabilizeLabels.size()))
                                               : tr("head motion not removed: no reference markers")));
  m_status->setToolTip(tr("%1 frames dropped for a missing marker; the PCA explains %2 % of the variance; "
                          "recommended by the %3")
                           .arg(static_cast<qlonglong>(frames.droppedFrames))
                           .arg(100.0 * plan.explainedVariance, 0, 'f', 1)
                           .arg(QString::fromStdString(plan.recommendationRule)));
  m_plot->setPlan(plan, m_shown->rig ? &*m_shown->rig : nullptr);
  if (!m_shown->rigError.isEmpty())
    m_status->setText(m_status->text() + QLatin1Char('\n') + tr("Not judged on the rig: %1").arg(m_shown->rigError));
  else if (m_shown->rig && m_shown->rig->cancelled)
    m_status->setText(m_status->text() + QLatin1Char('\n') + tr("Judging on the rig was cancelled."));
}

void LayoutPlanningPanel::followPlan()
{
  // A plan this panel did not just show (a recovered session's) is shown as if it had run here.
  if (m_plan.sharedResult() != m_shown)
    showResult(m_plan.sharedResult());
  if (m_shown && m_plot->selectedSize() != m_plan.selectedSize())
    (void)m_plot->setSelectedSize(m_plan.selectedSize());
  showSelectedSize();
}

namespace {

/// "PFA 0.035 · greedy 0.062 · random 0.073" for one size's rig measure ("—" where not judged).
QString rigSizeText(const LayoutSizeRigErrors& size)
{
  const auto value = [](const std::optional<RigLayoutError>& e) {
    return e && e->judged() ? QString::number(e->mse, 'g', 3) : QStringLiteral("—");
  };
  return LayoutPlanningPanel::tr("PFA %1 · greedy %2 · random %3")
      .arg(value(size.pfa), value(size.greedy),
           size.randomCount > 0 && std::isfinite(size.randomMse) ? QString::number(size.randomMse, 'g', 3)
                                                                 : QStringLiteral("—"));
}

} // namespace

void LayoutPlanningPanel::showSelectedSize()
{
  const LayoutPlanResult* result = m_plan.result();
  const LayoutSizeRigErrors* rigSize = result && result->rig ? result->rig->size(m_plan.selectedSize()) : nullptr;
  m_rigSummary->setVisible(rigSize != nullptr);
  if (rigSize)
    m_rigSummary->setText(tr("Rig-weight MSE at %1 markers (%2 of them bound; all %3 bound markers: 0): %4")
                              .arg(static_cast<qlonglong>(rigSize->markerCount))
                              .arg(static_cast<qlonglong>(rigSize->pfa ? rigSize->pfa->boundMarkers
                                                          : rigSize->greedy ? rigSize->greedy->boundMarkers
                                                                            : 0))
                              .arg(static_cast<qlonglong>(result->rig->boundMarkers))
                              .arg(rigSizeText(*rigSize)));
  m_markers->setRowCount(0);
  const ScoredLayout* layout = m_plan.selectedLayout();
  if (!layout) {
    setIdle(m_idle);
    return;
  }
  const LayoutFrames& frames = result->frames;
  const MarkerSymmetry& symmetry = result->symmetry;
  for (const Eigen::Index m : layout->markers) {
    const int row = m_markers->rowCount();
    m_markers->insertRow(row);
    const Eigen::Index mirror = symmetry.mirror(m);
    m_markers->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(frames.labels[static_cast<std::size_t>(m)])));
    m_markers->setItem(row, 1,
                       new QTableWidgetItem(mirror == m ? QString()
                                                        : QString::fromStdString(frames.labels[static_cast<std::size_t>(mirror)])));
    const auto unit = static_cast<std::size_t>(symmetry.unitOf(m));
    m_markers->setItem(row, 2,
                       new QTableWidgetItem(unit < layout->unitFrequency.size()
                                                ? QStringLiteral("%1 %").arg(100.0 * layout->unitFrequency[unit], 0, 'f', 1)
                                                : tr("—")));
  }
  m_markers->resizeColumnsToContents();
  setIdle(m_idle);  // the export buttons follow the selection
}

QString LayoutPlanningPanel::exportLabelList(const QString& path) const
{
  const std::vector<std::string> labels = m_plan.selectedLabels();
  if (labels.empty())
    return tr("There is no layout to export: run the plan and pick a marker count.");
  std::string text;
  for (const std::string& label : labels)
    text += label + "\n";
  try {
    writeFileAtomically(path.toStdString(), text);
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

QString LayoutPlanningPanel::exportMarkerSet(const QString& path) const
{
  const std::vector<std::string> labels = m_plan.captureLabels();
  if (labels.empty())
    return tr("There is no layout to export: run the plan and pick a marker count.");
  try {
    MarkerSet set = markerSetFromTake(subsetTake(m_document.take(), labels));
    // The pairs the plan kept together, rather than ones detected again on the template.
    set.pairs.clear();
    const auto indexOf = [&](const std::string& label) -> Eigen::Index {
      const auto it = std::find(set.labels.begin(), set.labels.end(), label);
      return it == set.labels.end() ? -1 : static_cast<Eigen::Index>(it - set.labels.begin());
    };
    const LayoutPlanResult& result = *m_plan.result();
    for (const auto& [a, b] : result.symmetry.pairs()) {
      const Eigen::Index i = indexOf(result.frames.labels[static_cast<std::size_t>(a)]);
      const Eigen::Index j = indexOf(result.frames.labels[static_cast<std::size_t>(b)]);
      if (i >= 0 && j >= 0)
        set.pairs.emplace_back(i, j);
    }
    writeMarkerSet(set, path.toStdString());
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

QString LayoutPlanningPanel::exportTake(const QString& path) const
{
  const std::vector<std::string> labels = m_plan.captureLabels();
  if (labels.empty())
    return tr("There is no layout to export: run the plan and pick a marker count.");
  try {
    writeTake(subsetTake(m_document.take(), labels), path.toStdString());
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

void LayoutPlanningPanel::exportWithDialog(const QString& title, const QString& filter,
                                           QString (LayoutPlanningPanel::*write)(const QString&) const)
{
  LayoutPlanningSettings settings;
  const QString folder = settings.exportFolder.get().isEmpty() ? QFileInfo(m_document.filePath()).absolutePath()
                                                               : settings.exportFolder.get();
  // The dialog asks before replacing an existing file.
  const QString path = QFileDialog::getSaveFileName(this, title, folder, filter);
  if (path.isEmpty())
    return;
  settings.exportFolder = QFileInfo(path).absolutePath();
  const QString error = (this->*write)(path);
  if (!error.isEmpty())
    QMessageBox::warning(this, title, tr("Could not write %1:\n%2").arg(path, error));
  else
    m_status->setText(tr("Wrote %1").arg(path));
}

} // namespace mocap::ui
