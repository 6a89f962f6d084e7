#include "panels/head_stabilisation_step.h"

#include "document/take_document.h"

#include "mocap/error.h"
#include "mocap/head_stabilization.h"

#include <QCoreApplication>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QStringList>

#include <algorithm>
#include <string>

namespace mocap::ui {

HeadStabilisationStep::HeadStabilisationStep(TakeDocument& document, QWidget* parent)
    : CleaningStep(parent), m_document(document)
{
  auto* form = new QFormLayout(this);
  auto* row = new QHBoxLayout;
  m_labels = new QLineEdit(this);
  m_labels->setObjectName(QStringLiteral("headReferenceLabels"));
  m_labels->setToolTip(tr("Head-mounted markers (at least three, comma separated) that move only with the head"));
  row->addWidget(m_labels, 1);
  auto* fromSelection = new QPushButton(tr("Use Selection"), this);
  row->addWidget(fromSelection);
  form->addRow(tr("Reference markers"), row);
  m_frame = new QSpinBox(this);
  m_frame->setRange(0, 1 << 30);
  m_frame->setSpecialValueText(tr("First complete frame"));
  m_frame->setToolTip(tr("Frame whose head pose becomes the stabilised pose"));
  form->addRow(tr("Reference frame"), m_frame);

  connect(fromSelection, &QPushButton::clicked, this, &HeadStabilisationStep::useSelection);
  connect(m_labels, &QLineEdit::editingFinished, this, &CleaningStep::changed);
  connect(m_frame, qOverload<int>(&QSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(&m_document, &TakeDocument::takeReset, this, &HeadStabilisationStep::guessReference);
  guessReference();
}

QString HeadStabilisationStep::title() const
{
  return tr("Stabilise head");
}

void HeadStabilisationStep::setReferenceLabels(const QString& labels)
{
  m_labels->setText(labels);
  emit changed();
}

void HeadStabilisationStep::guessReference()
{
  const Take& take = m_document.take();
  // A new take with the same labels (e.g. after tracking) keeps the user's choice.
  const QStringList current = m_labels->text().split(QLatin1Char(','), Qt::SkipEmptyParts);
  if (!current.isEmpty() && std::all_of(current.begin(), current.end(), [&](const QString& label) {
        return take.markerIndex(label.trimmed().toStdString()).has_value();
      }))
    return;
  QStringList labels;
  for (const Eigen::Index m : guessHeadReferenceMarkers(take))
    labels << QString::fromStdString(take.label(m));
  m_labels->setText(labels.join(QStringLiteral(",")));
  m_frame->setValue(0);
}

void HeadStabilisationStep::useSelection()
{
  const Take& take = m_document.take();
  QStringList labels;
  for (const Eigen::Index m : m_document.selection())
    labels << QString::fromStdString(take.label(m));
  setReferenceLabels(labels.join(QStringLiteral(",")));
}

StepJob HeadStabilisationStep::job() const
{
  const QStringList labels = m_labels->text().split(QLatin1Char(','), Qt::SkipEmptyParts);
  std::vector<std::string> names;
  for (const QString& label : labels)
    names.push_back(label.trimmed().toStdString());
  // The spin box counts frames as the take numbers them; 0 (its minimum) means automatic.
  const long long frameNumber = m_frame->value();
  return [names, frameNumber](const Take& take) {
    std::vector<Eigen::Index> markers;
    for (const std::string& name : names) {
      const auto index = take.markerIndex(name);
      if (!index)
        throw InvalidArgument(
            QCoreApplication::translate("HeadStabilisationStep", "There is no marker '%1'.")
                .arg(QString::fromStdString(name))
                .toStdString());
      markers.push_back(*index);
    }
    const Eigen::Index frame = frameNumber == 0 ? -1 : static_cast<Eigen::Index>(frameNumber - take.firstFrame());
    const HeadMotion motion = estimateHeadMotion(take, markers, frame);
    StepResult result;
    result.patches = headMotionRemovalPatches(take, motion);
    const int measured = static_cast<int>(std::count(motion.known.begin(), motion.known.end(), true));
    result.summary = QCoreApplication::translate("HeadStabilisationStep", "head pose measured in %1 of %2 frames")
                         .arg(measured)
                         .arg(take.frameCount());
    return result;
  };
}

} // namespace mocap::ui
