#include "panels/smoothing_step.h"

#include "document/view_state.h"
#include "views/display_units.h"

#include "mocap/cleaning/position_change.h"
#include "mocap/cleaning/smoothing.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>

namespace mocap::ui {

namespace {

// A change in the display unit with a hundredth of a millimetre visible: smoothing moves
// samples by fractions of a millimetre, finer than formatLength shows positions.
QString changeText(double value, LengthUnit from, LengthUnit to)
{
  const int decimals = to == LengthUnit::Millimetre ? 2 : to == LengthUnit::Centimetre ? 3 : 5;
  return QString::number(value * millimetresPer(from) / millimetresPer(to), 'f', decimals);
}

} // namespace

SmoothingStep::SmoothingStep(QWidget* parent) : CleaningStep(parent)
{
  const SmoothOptions defaults;
  auto* form = new QFormLayout(this);
  m_method = new QComboBox(this);
  m_method->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);  // the dock stays narrow
  m_method->setMinimumContentsLength(18);
  m_method->addItem(tr("GCV smoothing spline (Woltring)"), static_cast<int>(SmoothMethod::Gcvspl));
  m_method->addItem(tr("B-spline (Zhang et al., smoothing)"), static_cast<int>(SmoothMethod::BSpline));
  m_method->addItem(tr("Butterworth (zero lag)"), static_cast<int>(SmoothMethod::Butterworth));
  m_method->addItem(tr("Savitzky–Golay"), static_cast<int>(SmoothMethod::SavGol));
  m_method->setItemData(0, tr("A smoothing spline whose stiffness is chosen per marker by generalized "
                              "cross-validation: no setting to tune"), Qt::ToolTipRole);
  m_method->setItemData(1, tr("A least-squares B-spline with knots every few frames (the paper's smoothing)"),
                        Qt::ToolTipRole);
  m_method->setItemData(2, tr("A low-pass filter run forwards and backwards, so nothing lags; cuts motion faster "
                              "than the cutoff"), Qt::ToolTipRole);
  m_method->setItemData(3, tr("A polynomial fitted in a sliding window: keeps peaks sharper than a low-pass filter"),
                        Qt::ToolTipRole);
  tipFollowsCurrentItem(*m_method);
  form->addRow(tr("Method"), m_method);
  m_degree = new QSpinBox(this);
  m_degree->setRange(2, 7);
  m_degree->setValue(defaults.degree);
  m_degree->setToolTip(tr("B-spline degree: 3 is cubic, the paper's \"third order\""));
  form->addRow(tr("Degree"), m_degree);
  m_knotSpacing = new QDoubleSpinBox(this);
  m_knotSpacing->setRange(1.5, 100.0);
  m_knotSpacing->setValue(defaults.knotSpacing);
  m_knotSpacing->setSuffix(tr(" frames"));
  form->addRow(tr("Knot spacing"), m_knotSpacing);
  m_cutoff = new QDoubleSpinBox(this);
  m_cutoff->setRange(0.5, 100.0);
  m_cutoff->setValue(defaults.cutoffHz);
  m_cutoff->setSuffix(tr(" Hz"));
  form->addRow(tr("Cutoff"), m_cutoff);
  m_window = new QSpinBox(this);
  m_window->setRange(5, 101);
  m_window->setSingleStep(2);
  m_window->setValue(defaults.savgolWindow);
  m_window->setSuffix(tr(" frames"));
  form->addRow(tr("Window"), m_window);
  updateEnabled();
  connect(m_method, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] {
    updateEnabled();
    emit changed();
  });
  connect(m_degree, qOverload<int>(&QSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(m_knotSpacing, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(m_cutoff, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(m_window, qOverload<int>(&QSpinBox::valueChanged), this, &CleaningStep::changed);
}

void SmoothingStep::updateEnabled()
{
  const auto method = static_cast<SmoothMethod>(m_method->currentData().toInt());
  m_degree->setEnabled(method == SmoothMethod::BSpline);
  m_knotSpacing->setEnabled(method == SmoothMethod::BSpline);
  m_cutoff->setEnabled(method == SmoothMethod::Butterworth);
  m_window->setEnabled(method == SmoothMethod::SavGol);
}

QString SmoothingStep::title() const
{
  return tr("Smoothing");
}

SmoothOptions SmoothingStep::currentOptions() const
{
  SmoothOptions options;
  options.method = static_cast<SmoothMethod>(m_method->currentData().toInt());
  options.degree = m_degree->value();
  options.knotSpacing = m_knotSpacing->value();
  options.cutoffHz = m_cutoff->value();
  options.savgolWindow = m_window->value() | 1;  // odd
  return options;
}

void SmoothingStep::addToPreset(CleanOptions& preset) const
{
  preset.smooth = currentOptions();
}

QString SmoothingStep::appliedSummary(const std::vector<SamplePatch>& applied, const StepResult&) const
{
  return samplesOnMarkers(countPatches(applied), tr("1 sample smoothed"), tr("%1 samples smoothed"));
}

bool SmoothingStep::loadPreset(const CleanOptions& preset)
{
  if (!preset.smooth)
    return false;
  const SmoothOptions& smooth = *preset.smooth;
  selectMethod(*m_method, static_cast<int>(smooth.method));
  m_degree->setValue(static_cast<int>(smooth.degree));
  m_knotSpacing->setValue(smooth.knotSpacing);
  m_cutoff->setValue(smooth.cutoffHz);
  m_window->setValue(static_cast<int>(smooth.savgolWindow));
  return true;
}

StepJob SmoothingStep::job() const
{
  return [options = currentOptions(), unit = m_displayUnit](const Take& take, const JobControl& control) {
    StepResult result;
    result.patches = smoothTake(take, options, control);
    result.summary = QCoreApplication::translate("SmoothingStep", "%1 smoothing")
                         .arg(QString::fromUtf8(smoothMethodName(options.method).data(),
                                                static_cast<int>(smoothMethodName(options.method).size())));
    // What a technician judges a smoothing by: how far it moves the samples.
    const PositionChange change = positionChange(take, result.patches);
    if (change.samples > 0)
      result.summary += QCoreApplication::translate("SmoothingStep", ": moves samples by RMS %1 %3, at most %2 %3 (%4, frame %5)")
                            .arg(changeText(change.rms, take.units(), unit),
                                 changeText(change.max, take.units(), unit), unitLabel(unit),
                                 QString::fromStdString(take.label(change.maxMarker)))
                            .arg(static_cast<qlonglong>(take.firstFrame() + change.maxFrame));
    return result;
  };
}

void SmoothingStep::observe(const ViewState& state)
{
  setDisplayUnit(state.displayUnit());
  connect(&state, &ViewState::displayUnitChanged, this, &SmoothingStep::setDisplayUnit);
}

} // namespace mocap::ui
