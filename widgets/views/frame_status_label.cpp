#include "views/frame_status_label.h"

#include "document/take_document.h"
#include "views/steady_label.h"

#include <algorithm>

namespace mocap::ui {

FrameStatusLabel::FrameStatusLabel(const TakeDocument& document, QWidget* parent) : QLabel(parent), m_document(document)
{
  setObjectName(QStringLiteral("frameStatus"));
  connect(&document, &TakeDocument::currentFrameChanged, this, &FrameStatusLabel::showFrame);
  connect(&document, &TakeDocument::selectionChanged, this, &FrameStatusLabel::showFrame);
}

QString FrameStatusLabel::lineFor(Eigen::Index frame, std::size_t selected) const
{
  // The take's range in the file's numbering: a take starting at frame 63 is not "555 of 493".
  const Take& take = m_document.take();
  return tr("Frame %1 of %2–%3 — %4 markers selected")
      .arg(static_cast<qlonglong>(take.firstFrame() + frame))
      .arg(static_cast<qlonglong>(take.firstFrame()))
      .arg(static_cast<qlonglong>(take.firstFrame() + std::max<Eigen::Index>(take.frameCount() - 1, 0)))
      .arg(static_cast<qulonglong>(selected));
}

void FrameStatusLabel::showFrame()
{
  const Take& take = m_document.take();
  const std::pair<Eigen::Index, Eigen::Index> fitted{take.frameCount(), take.markerCount()};
  if (fitted != m_fitsTake) {  // sized for the take's widest line
    fixLabelSizeFor(*this, lineFor(take.frameCount() - 1, static_cast<std::size_t>(take.markerCount())));
    m_fitsTake = fitted;
  }
  setText(lineFor(m_document.currentFrame(), m_document.selection().size()));
}

} // namespace mocap::ui
