#include "panels/spike_step.h"

#include "document/take_document.h"

#include "mocap/cleaning/flags_beside_repairs.h"
#include "mocap/cleaning/spike_detection.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QListWidget>

namespace mocap::ui {

namespace {
constexpr int kMarkerRole = Qt::UserRole;
constexpr int kFrameRole = Qt::UserRole + 1;
} // namespace

SpikeStep::SpikeStep(TakeDocument& document, QWidget* parent) : CleaningStep(parent), m_document(document)
{
  auto* form = new QFormLayout(this);
  m_method = new QComboBox(this);
  m_method->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);  // the dock stays narrow
  m_method->setMinimumContentsLength(18);
  m_method->addItem(tr("Robust (local fit + MAD)"), static_cast<int>(SpikeMethod::Robust));
  m_method->addItem(tr("Paper method: step test (Zhang et al., bad points)"), static_cast<int>(SpikeMethod::Paper));
  m_method->setItemData(0, tr("Judges each sample against a robust local fit of its neighbours"), Qt::ToolTipRole);
  m_method->setItemData(1,
                        tr("Flags a sample whose steps to both neighbours exceed a multiple of the mean step "
                           "(the paper as written, one pass); repairs it from its neighbours"),
                        Qt::ToolTipRole);
  tipFollowsCurrentItem(*m_method);
  form->addRow(tr("Method"), m_method);
  m_factor = new QDoubleSpinBox(this);
  m_factor->setRange(1.0, 10.0);
  m_factor->setSingleStep(0.1);
  m_factor->setValue(SpikeOptions{}.factor);
  m_factor->setToolTip(tr("Paper: a sample is bad when both adjacent steps exceed this multiple of the mean step"));
  form->addRow(tr("Factor"), m_factor);
  m_threshold = new QDoubleSpinBox(this);
  m_threshold->setRange(2.0, 30.0);
  m_threshold->setSingleStep(0.5);
  m_threshold->setValue(SpikeOptions{}.threshold);
  m_threshold->setToolTip(tr("Robust: flag samples this many robust standard deviations off the local fit"));
  form->addRow(tr("Threshold"), m_threshold);
  m_settle = new QCheckBox(tr("Look again until nothing new"), this);
  m_settle->setObjectName(QStringLiteral("settle"));
  m_settle->setToolTip(tr("A glitch longer than a few frames is found a part at a time, its worst samples first, so "
                          "detecting again after a repair finds the rest beside the repaired samples. On, the robust "
                          "detector repeats itself on the repaired curve until it finds nothing new: whole glitches "
                          "are flagged at once (more flags), and a second detection finds next to nothing."));
  form->addRow(m_settle);
  m_flags = new QListWidget(this);
  m_flags->setToolTip(tr("Click to go to a flag; uncheck to keep that sample"));
  form->addRow(m_flags);
  auto updateEnabled = [this] {
    const bool paper = m_method->currentData().toInt() == static_cast<int>(SpikeMethod::Paper);
    m_factor->setEnabled(paper);
    m_threshold->setEnabled(!paper);
    m_settle->setEnabled(!paper);  // eq 9 as written: one pass
  };
  updateEnabled();
  connect(m_method, qOverload<int>(&QComboBox::currentIndexChanged), this, [this, updateEnabled] {
    updateEnabled();
    emit changed();
  });
  connect(m_factor, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(m_threshold, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(m_settle, &QCheckBox::toggled, this, &CleaningStep::changed);
  connect(m_flags, &QListWidget::currentItemChanged, this, [this](QListWidgetItem* item) {
    if (!item)
      return;
    m_document.setSelection({item->data(kMarkerRole).value<qlonglong>()});
    m_document.setCurrentFrame(item->data(kFrameRole).value<qlonglong>());
  });
}

QString SpikeStep::title() const
{
  return tr("Bad points");
}

SpikeOptions SpikeStep::currentOptions() const
{
  SpikeOptions options;
  options.method = static_cast<SpikeMethod>(m_method->currentData().toInt());
  options.factor = m_factor->value();
  options.threshold = m_threshold->value();
  options.maxPasses = m_settle->isChecked() ? 100 : 1;
  return options;
}

void SpikeStep::addToPreset(CleanOptions& preset) const
{
  preset.spikes = currentOptions();
}

bool SpikeStep::loadPreset(const CleanOptions& preset)
{
  if (!preset.spikes)
    return false;
  selectMethod(*m_method, static_cast<int>(preset.spikes->method));
  m_factor->setValue(preset.spikes->factor);
  m_threshold->setValue(preset.spikes->threshold);
  m_settle->setChecked(preset.spikes->maxPasses > 1);
  return true;
}

StepJob SpikeStep::job() const
{
  return [options = currentOptions(), repairs = m_repairs](const Take& take, const JobControl& control) {
    StepResult result;
    result.detection = true;
    const std::vector<SpikeFlag> flags = detectSpikes(take, options, control);
    for (const SpikeFlag& flag : flags)
      result.flags.emplace_back(flag.marker, flag.frame);
    result.patches = replaceSpikes(take, flags);
    const int count = static_cast<int>(flags.size());  // a plain variable, so lupdate sees the plural
    result.summary = QCoreApplication::translate("SpikeStep", "%n bad point(s) found", nullptr, count);
    const auto beside = static_cast<int>(flagsBesideRepairs(take, flags, repairs));  // plain, for lupdate's plural
    if (beside > 0)  // why a repair seems to breed flags, and what to do about it
      result.summary += QCoreApplication::translate(
          "SpikeStep",
          "; %n beside samples just repaired: a glitch longer than a few frames is found a part at a "
          "time (its worst samples first). Repair these too, or turn on \"Look again until nothing new\" "
          "to flag whole glitches at once",
          nullptr, beside);
    return result;
  };
}

void SpikeStep::showResult(const StepResult& result)
{
  m_flags->clear();
  const Take& take = m_document.take();
  for (const auto& [marker, frame] : result.flags) {
    auto* item = new QListWidgetItem(tr("%1 at frame %2").arg(QString::fromStdString(take.label(marker)))
                                         .arg(static_cast<qlonglong>(take.firstFrame() + frame)),
                                     m_flags);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(Qt::Checked);
    item->setData(kMarkerRole, static_cast<qlonglong>(marker));
    item->setData(kFrameRole, static_cast<qlonglong>(frame));
  }
}

void SpikeStep::applied(const std::vector<SamplePatch>& patches)
{
  m_repairs = patches;
}

QString SpikeStep::appliedSummary(const std::vector<SamplePatch>& applied, const StepResult&) const
{
  return samplesOnMarkers(countPatches(applied), tr("1 sample repaired"), tr("%1 samples repaired"));
}

std::vector<SamplePatch> SpikeStep::patchesToApply(const Take& take, const StepResult&) const
{
  std::vector<SpikeFlag> accepted;
  for (int i = 0; i < m_flags->count(); ++i) {
    const QListWidgetItem* item = m_flags->item(i);
    if (item->checkState() == Qt::Checked)
      accepted.push_back({item->data(kMarkerRole).value<qlonglong>(), item->data(kFrameRole).value<qlonglong>()});
  }
  return replaceSpikes(take, accepted);
}

} // namespace mocap::ui
