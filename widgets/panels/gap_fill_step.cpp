#include "panels/gap_fill_step.h"

#include "document/take_document.h"
#include "models/fill_rule_text.h"
#include "models/gap_table_model.h"

#include "mocap/cleaning/fill/gap_fill.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QListWidget>
#include <QSignalBlocker>
#include <QSpinBox>

#include <algorithm>
#include <array>
#include <cmath>

namespace mocap::ui {

namespace {

constexpr int kMarkerRole = Qt::UserRole;
constexpr int kFrameRole = Qt::UserRole + 1;

// "No gap filled", "1 gap filled, 66 samples": singular and plural spelled out, as the source
// language has no catalogue.
QString filledText(int filledGaps, int samples)
{
  if (filledGaps == 0)
    return QCoreApplication::translate("GapFillStep", "No gap filled");
  return (filledGaps == 1 ? QCoreApplication::translate("GapFillStep", "1 gap filled")
                          : QCoreApplication::translate("GapFillStep", "%1 gaps filled").arg(filledGaps)) +
         (samples == 1 ? QCoreApplication::translate("GapFillStep", ", 1 sample")
                       : QCoreApplication::translate("GapFillStep", ", %1 samples").arg(samples));
}

// "1 gap filled, 66 samples; 3 left open (2 longer than 0.5 s, 1 edge gap)".
QString summary(int filledGaps, int samples, const std::array<int, 7>& openByCause, double maxGapSeconds)
{
  const QString text = filledText(filledGaps, samples);
  int open = 0;
  for (int count : openByCause)
    open += count;
  if (open == 0)
    return text;
  QStringList causes;
  const auto count = [&](UnfilledCause cause) { return openByCause[static_cast<std::size_t>(cause)]; };
  if (const int n = count(UnfilledCause::TooLong))
    causes << QCoreApplication::translate("GapFillStep", "%1 longer than %2").arg(n).arg(secondsText(maxGapSeconds));
  if (const int n = count(UnfilledCause::EdgeGap))
    causes << QCoreApplication::translate("GapFillStep", "%n edge gap(s)", nullptr, n);
  if (const int n = count(UnfilledCause::RarelyValid))
    causes << QCoreApplication::translate("GapFillStep", "%n on rarely seen markers", nullptr, n);
  if (const int n = count(UnfilledCause::NeverValid))
    causes << QCoreApplication::translate("GapFillStep", "%n on markers never seen", nullptr, n);
  if (const int n = count(UnfilledCause::Method))
    causes << QCoreApplication::translate("GapFillStep", "%n the method could not fill", nullptr, n);
  if (const int n = count(UnfilledCause::ModelOutput))
    causes << QCoreApplication::translate("GapFillStep", "%n on model outputs", nullptr, n);
  return text + QCoreApplication::translate("GapFillStep", "; %n left open", nullptr, open) + QStringLiteral(" (") +
         causes.join(QStringLiteral(", ")) + QStringLiteral(")");
}

} // namespace

GapFillStep::GapFillStep(TakeDocument& document, QWidget* parent) : CleaningStep(parent), m_document(document)
{
  auto* form = new QFormLayout(this);
  m_method = new QComboBox(this);
  m_method->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);  // the dock stays narrow
  m_method->setMinimumContentsLength(18);
  // The order a technician tries them in; the names are the gap list's, so both read the same.
  for (FillMethod method : {FillMethod::Auto, FillMethod::Rigid, FillMethod::Pca, FillMethod::Spline, FillMethod::Linear,
                            FillMethod::Zhang3, FillMethod::ZhangN, FillMethod::Guenter, FillMethod::LinOuhyoung}) {
    m_method->addItem(GapTableModel::methodTitle(method), static_cast<int>(method));
    m_method->setItemData(m_method->count() - 1, GapTableModel::methodTip(method), Qt::ToolTipRole);
  }
  tipFollowsCurrentItem(*m_method);
  form->addRow(tr("Method"), m_method);
  m_neighbours = new QSpinBox(this);
  m_neighbours->setRange(1, 30);
  m_neighbours->setValue(FillOptions{}.neighbours);
  form->addRow(tr("Neighbours"), m_neighbours);

  m_maxGapSeconds = FillOptions{}.maxGapSeconds;
  m_maxGapSecondsBox = new QDoubleSpinBox(this);
  m_maxGapSecondsBox->setObjectName(QStringLiteral("maxGapSeconds"));
  m_maxGapSecondsBox->setRange(0.0, 3600.0);
  m_maxGapSecondsBox->setDecimals(3);
  m_maxGapSecondsBox->setSingleStep(0.1);
  m_maxGapSecondsBox->setSpecialValueText(tr("unlimited"));
  m_maxGapSecondsBox->setSuffix(tr(" s"));
  m_maxGapFrames = new QSpinBox(this);
  m_maxGapFrames->setObjectName(QStringLiteral("maxGapFrames"));
  m_maxGapFrames->setRange(0, 1000000);
  m_maxGapFrames->setSpecialValueText(tr("unlimited"));
  m_maxGapFrames->setSuffix(tr(" frames"));
  const QString longestTip = tr("Longer gaps are left open: filling them would invent motion");
  m_maxGapSecondsBox->setToolTip(longestTip);
  m_maxGapFrames->setToolTip(longestTip);
  // One row each, so the dock stays narrow enough for the 3D view at 1280 px.
  form->addRow(tr("Longest gap"), m_maxGapSecondsBox);
  form->addRow(tr("= frames"), m_maxGapFrames);
  showMaxGap();

  m_extrapolate = new QCheckBox(tr("Extrapolate edge gaps"), this);
  m_extrapolate->setToolTip(tr("Fill before a marker's first and after its last valid sample (invents motion "
                               "nobody measured; off by default)"));
  m_extrapolate->setObjectName(QStringLiteral("extrapolate"));
  m_extrapolate->setChecked(FillOptions{}.extrapolate);
  form->addRow(m_extrapolate);
  m_minValid = new QSpinBox(this);
  m_minValid->setObjectName(QStringLiteral("minValid"));
  m_minValid->setRange(0, 100);
  m_minValid->setSuffix(tr(" % of the take"));
  m_minValid->setSpecialValueText(tr("fill every marker"));
  m_minValid->setValue(static_cast<int>(std::lround(100.0 * FillOptions{}.minValidFraction)));
  m_minValid->setToolTip(tr("Markers seen in fewer frames are left open, unless they are selected and "
                            "\"Selected markers only\" is on"));
  form->addRow(tr("Skip markers seen under"), m_minValid);
  m_open = new QListWidget(this);
  m_open->setObjectName(QStringLiteral("openGaps"));
  m_open->setToolTip(tr("Gaps left open and why; click one to go there"));
  form->addRow(tr("Left open"), m_open);

  connect(m_method, qOverload<int>(&QComboBox::currentIndexChanged), this, &CleaningStep::changed);
  connect(m_neighbours, qOverload<int>(&QSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(m_maxGapSecondsBox, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
          &GapFillStep::setMaxGapSeconds);
  connect(m_maxGapFrames, qOverload<int>(&QSpinBox::valueChanged), this,
          [this](int frames) { setMaxGapSeconds(static_cast<double>(frames) / frameRate()); });
  connect(m_extrapolate, &QCheckBox::toggled, this, &CleaningStep::changed);
  connect(m_minValid, qOverload<int>(&QSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(&document, &TakeDocument::rangeChanged, this, &CleaningStep::changed);
  connect(&document, &TakeDocument::takeReset, this, &GapFillStep::showMaxGap);  // a new rate
  connect(m_open, &QListWidget::currentItemChanged, this, [this](QListWidgetItem* item) {
    if (!item)
      return;
    m_document.setSelection({item->data(kMarkerRole).value<qlonglong>()});
    m_document.setCurrentFrame(item->data(kFrameRole).value<qlonglong>());
  });
}

QString GapFillStep::title() const
{
  return tr("Gaps");
}

double GapFillStep::frameRate() const
{
  const double rate = m_document.hasTake() ? m_document.take().frameRate() : 0.0;
  return rate > 0.0 ? rate : 100.0;
}

void GapFillStep::setMaxGapSeconds(double seconds)
{
  seconds = std::max(0.0, seconds);
  if (seconds == m_maxGapSeconds)
    return;
  m_maxGapSeconds = seconds;
  showMaxGap();
  emit changed();
}

void GapFillStep::showMaxGap()
{
  const QSignalBlocker blockSeconds(m_maxGapSecondsBox);
  const QSignalBlocker blockFrames(m_maxGapFrames);
  m_maxGapSecondsBox->setValue(m_maxGapSeconds);
  FillOptions options;
  options.maxGapSeconds = m_maxGapSeconds;
  const Eigen::Index frames = longestGapFrames(options, frameRate());
  m_maxGapFrames->setValue(static_cast<int>(std::min<Eigen::Index>(frames, m_maxGapFrames->maximum())));
}

FillOptions GapFillStep::currentOptions() const
{
  FillOptions options;
  options.method = static_cast<FillMethod>(m_method->currentData().toInt());
  options.neighbours = m_neighbours->value();
  options.maxGap = 0;
  options.maxGapSeconds = m_maxGapSeconds;
  options.extrapolate = m_extrapolate->isChecked();
  options.minValidFraction = m_minValid->value() / 100.0;
  return options;
}

void GapFillStep::addToPreset(CleanOptions& preset) const
{
  preset.fill = currentOptions();
}

bool GapFillStep::loadPreset(const CleanOptions& preset)
{
  if (!preset.fill)
    return false;
  const FillOptions& fill = *preset.fill;
  selectMethod(*m_method, static_cast<int>(fill.method));
  m_neighbours->setValue(static_cast<int>(fill.neighbours));
  m_extrapolate->setChecked(fill.extrapolate);
  m_minValid->setValue(static_cast<int>(std::lround(fill.minValidFraction * 100.0)));
  setMaxGapSeconds(fill.maxGap > 0 ? static_cast<double>(fill.maxGap) / frameRate() : fill.maxGapSeconds);
  return true;
}

StepJob GapFillStep::job() const
{
  FillOptions options = currentOptions();
  const StepScope scope = this->scope();
  if (scope.markersOnly)
    options.fillAnyway = scope.markers;  // a technician who selects a marker means it
  return [options, scope](const Take& take, const JobControl& control) {
    FillResult filled = fillGaps(take, options, control);
    // The gaps in scope: the selected markers (when limited to them) and, with a range on the
    // curves, the gaps overlapping it; the summary counts only these, as Apply changes only these.
    const bool ranged = scope.first <= scope.last;
    const auto inScope = [&](Eigen::Index marker, Eigen::Index first, Eigen::Index last) {
      return scope.hasMarker(marker) && (!ranged || (last >= scope.first && first <= scope.last));
    };
    StepResult result;
    std::array<int, 7> openByCause{};
    for (const GapFillReport& report : filled.gaps) {
      const Eigen::Index end = report.gap.firstFrame + report.gap.length - 1;
      if (report.filled || !inScope(report.gap.marker, report.gap.firstFrame, end))
        continue;
      ++openByCause[static_cast<std::size_t>(report.cause)];
      const QString where = tr("%1, frames %2–%3 (%4)")
                                .arg(QString::fromStdString(take.label(report.gap.marker)))
                                .arg(static_cast<qlonglong>(take.firstFrame() + report.gap.firstFrame))
                                .arg(static_cast<qlonglong>(take.firstFrame() + end))
                                .arg(static_cast<qlonglong>(report.gap.length));
      result.notes.push_back({report.gap.marker, report.gap.firstFrame,
                              where + QStringLiteral(": ") + fillRuleText(report, take, options)});
    }
    int samples = 0;
    for (SamplePatch& patch : filled.patches) {
      if (!inScope(patch.marker, patch.frames.front(), patch.frames.back()))
        continue;
      samples +=
          static_cast<int>(scope.rangeOnly ? patchWithin(patch, scope.first, scope.last).size() : patch.size());
      result.patches.push_back(std::move(patch));
    }
    const int filledCount = static_cast<int>(result.patches.size());
    result.summary = summary(filledCount, samples, openByCause, options.maxGapSeconds);
    return result;
  };
}

QString GapFillStep::appliedSummary(const std::vector<SamplePatch>& applied, const StepResult& result) const
{
  const QString text = filledText(static_cast<int>(applied.size()), countPatches(applied).samples);
  const auto open = static_cast<int>(result.notes.size());
  if (open == 0)
    return text;
  QStringList first;
  for (std::size_t i = 0; i < result.notes.size() && i < 3; ++i)
    first << result.notes[i].text;
  if (open > 3)
    first << QStringLiteral("…");
  return text + tr("; %1 left open: ").arg(open) + first.join(QStringLiteral("; "));
}

void GapFillStep::showResult(const StepResult& result)
{
  m_open->clear();
  for (const ReviewNote& note : result.notes) {
    auto* item = new QListWidgetItem(note.text, m_open);
    item->setToolTip(note.text);  // the list is narrow in the dock
    item->setData(kMarkerRole, static_cast<qlonglong>(note.marker));
    item->setData(kFrameRole, static_cast<qlonglong>(note.frame));
  }
}

} // namespace mocap::ui
