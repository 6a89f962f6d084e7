#include "panels/head_stabilization_step.h"

#include "document/take_document.h"
#include "panels/reference_markers_row.h"

#include "mocap/base/error.h"
#include "mocap/cleaning/head_stabilization.h"

#include <QCoreApplication>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>

#include <algorithm>

namespace mocap::ui {

HeadStabilizationStep::HeadStabilizationStep(TakeDocument& document, QWidget* parent)
    : CleaningStep(parent), m_document(document)
{
  auto* form = new QFormLayout(this);
  m_reference = new ReferenceMarkersRow(
      document, tr("Head-mounted markers that move only with the head: the head pose of every frame is measured "
                   "on them."),
      this);
  connect(m_reference, &ReferenceMarkersRow::editRequested, this,
          &HeadStabilizationStep::editReferenceMarkersRequested);
  form->addRow(tr("Reference markers"), m_reference);
  m_frame = new QSpinBox(this);
  m_frame->setRange(0, 1 << 30);
  m_frame->setSpecialValueText(tr("First complete frame"));
  m_frame->setToolTip(tr("Frame whose head pose becomes the stabilized pose"));
  form->addRow(tr("Reference frame"), m_frame);
  auto* scope = new QLabel(tr("Moves all markers in all frames into the head frame: \"Selected markers only\" and "
                              "\"Selected frame range only\" do not apply to this step."),
                           this);
  scope->setObjectName(QStringLiteral("wholeTakeNote"));
  scope->setWordWrap(true);
  form->addRow(scope);

  connect(m_frame, qOverload<int>(&QSpinBox::valueChanged), this, &CleaningStep::changed);
  connect(&m_document, &TakeDocument::referenceMarkersChanged, this, &CleaningStep::changed);
  connect(&m_document, &TakeDocument::takeReset, this, [this] { m_frame->setValue(0); });
}

QString HeadStabilizationStep::title() const
{
  return tr("Stabilize head");
}

QString HeadStabilizationStep::tabTitle() const
{
  return tr("Head", "the Cleaning panel's tab of Stabilize head");
}

StepJob HeadStabilizationStep::job() const
{
  // Indices into the document's take, of which the job gets a copy taken at the same moment.
  const std::vector<Eigen::Index> markers = m_document.referenceMarkers();
  // The spin box counts frames as the take numbers them; 0 (its minimum) means automatic.
  const long long frameNumber = m_frame->value();
  return [markers, frameNumber](const Take& take, const JobControl& control) {
    control.checkpoint(0.0);
    if (markers.empty())
      throw InvalidArgument(QCoreApplication::translate("HeadStabilizationStep",
                                                        "No reference markers: choose them in Marker ▸ Reference "
                                                        "Markers…")
                                .toStdString());
    const Eigen::Index frame = frameNumber == 0 ? -1 : static_cast<Eigen::Index>(frameNumber - take.firstFrame());
    const HeadMotion motion = estimateHeadMotion(take, markers, frame);
    StepResult result;
    result.patches = headMotionRemovalPatches(take, motion);
    const int measured = static_cast<int>(std::count(motion.known.begin(), motion.known.end(), true));
    result.summary = QCoreApplication::translate("HeadStabilizationStep", "head pose measured in %1 of %2 frames")
                         .arg(measured)
                         .arg(take.frameCount());
    return result;
  };
}

} // namespace mocap::ui
