#include "panels/gap_fill_step.h"

#include "document/take_document.h"

#include "mocap/gap_fill.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QSpinBox>

#include <algorithm>

namespace mocap::ui {

GapFillStep::GapFillStep(TakeDocument& document, QWidget* parent) : CleaningStep(parent), m_document(document)
{
  auto* form = new QFormLayout(this);
  m_method = new QComboBox(this);
  const std::pair<FillMethod, QString> methods[] = {
      {FillMethod::Auto, tr("Auto (best blend)")},
      {FillMethod::Rigid, tr("Rigid neighbours")},
      {FillMethod::Pca, tr("PCA (marker correlations)")},
      {FillMethod::Spline, tr("Cubic spline")},
      {FillMethod::Linear, tr("Linear")},
      {FillMethod::Zhang3, tr("Paper: three neighbours (eqs 3–5)")},
      {FillMethod::ZhangN, tr("Paper: n neighbours (eqs 6–7)")},
      {FillMethod::Guenter, tr("Neighbour average (Guenter)")},
      {FillMethod::LinOuhyoung, tr("Distance-weighted neighbours (Lin–Ouhyoung)")},
  };
  for (const auto& [method, name] : methods)
    m_method->addItem(name, static_cast<int>(method));
  form->addRow(tr("Method"), m_method);
  m_neighbours = new QSpinBox(this);
  m_neighbours->setRange(1, 30);
  m_neighbours->setValue(FillOptions{}.neighbours);
  form->addRow(tr("Neighbours"), m_neighbours);
  m_maxGap = new QSpinBox(this);
  m_maxGap->setRange(0, 1000000);
  m_maxGap->setSpecialValueText(tr("unlimited"));
  m_maxGap->setSuffix(tr(" frames"));
  form->addRow(tr("Longest gap"), m_maxGap);
  connect(m_method, qOverload<int>(&QComboBox::currentIndexChanged), this, &CleaningStep::changed);
  connect(m_neighbours, qOverload<int>(&QSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(m_maxGap, qOverload<int>(&QSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(&document, &TakeDocument::rangeChanged, this, &CleaningStep::changed);
}

QString GapFillStep::title() const
{
  return tr("Gaps");
}

StepJob GapFillStep::job() const
{
  FillOptions options;
  options.method = static_cast<FillMethod>(m_method->currentData().toInt());
  options.neighbours = m_neighbours->value();
  options.maxGap = m_maxGap->value();
  const bool ranged = m_document.hasRange();
  const Eigen::Index first = m_document.rangeFirst(), last = m_document.rangeLast();
  return [options, ranged, first, last](const Take& take) {
    FillResult filled = fillGaps(take, options);
    StepResult result;
    int unfilled = 0;
    for (std::size_t i = 0; i < filled.gaps.size(); ++i) {
      const GapFillReport& report = filled.gaps[i];
      const Eigen::Index end = report.gap.firstFrame + report.gap.length - 1;
      if (ranged && (end < first || report.gap.firstFrame > last))
        continue;
      unfilled += report.filled ? 0 : 1;
    }
    for (SamplePatch& patch : filled.patches) {
      if (ranged && (patch.frames.back() < first || patch.frames.front() > last))
        continue;
      result.patches.push_back(std::move(patch));
    }
    const int filledCount = static_cast<int>(result.patches.size());  // plain variable: lupdate sees the plural
    result.summary = QCoreApplication::translate("GapFillStep", "%n gap(s) filled", nullptr, filledCount);
    if (unfilled > 0)
      result.summary += QCoreApplication::translate("GapFillStep", ", %n left open", nullptr, unfilled);
    return result;
  };
}

} // namespace mocap::ui
