#include "actions/head_stabilized_view_action.h"

#include "document/take_document.h"
#include "document/view_state.h"
#include "views/status_timeout.h"

#include <QAction>
#include <QMessageBox>
#include <QWidget>

#include <exception>

namespace mocap::ui {

HeadStabilizedViewAction::HeadStabilizedViewAction(TakeDocument& document, ViewState& view, QWidget& dialogParent,
                                                   QObject* parent)
    : QObject(parent), m_document(document), m_view(view), m_dialogParent(dialogParent), m_action(new QAction(this))
{
  m_action->setText(tr("&Head-Stabilized View"));
  m_action->setObjectName(QStringLiteral("headStabilizedViewAction"));
  m_action->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
  m_action->setCheckable(true);
  m_action->setToolTip(tr("Show the markers in the head frame of the reference markers (a view setting; the take "
                          "is not changed)"));
  connect(m_action, &QAction::triggered, this, &HeadStabilizedViewAction::setOn);
  connect(&view, &ViewState::headReferenceChanged, this,
          [this] { m_action->setChecked(!m_view.headReference().empty()); });
  // The view drops its head pose when markers shift or a take is set: follow the document's set.
  connect(&document, &TakeDocument::markersChanged, this, &HeadStabilizedViewAction::followReferenceMarkers);
  connect(&document, &TakeDocument::referenceMarkersChanged, this, &HeadStabilizedViewAction::followReferenceMarkers);
  connect(&document, &TakeDocument::takeReset, this, &HeadStabilizedViewAction::followReferenceMarkers);
}

void HeadStabilizedViewAction::setOn(bool on)
{
  if (!on) {
    m_view.setHeadReference({});
    m_action->setChecked(false);
    emit message(tr("3D view in the lab frame"), kStatusMessageMs);
    return;
  }
  const QString error = m_document.referenceMarkers().size() < 3
                            ? tr("Choose at least three reference markers first (Marker ▸ Reference Markers…).")
                            : headPoseProblem();
  m_action->setChecked(error.isEmpty());
  if (!error.isEmpty()) {
    QMessageBox::warning(&m_dialogParent, tr("Head-Stabilized View"), error);
    return;
  }
  m_view.setHeadReference(m_document.referenceMarkers());
  emit message(tr("3D view stabilized on the reference markers (Ctrl+B again for the lab frame)"), kStatusMessageMs);
}

QString HeadStabilizedViewAction::headPoseProblem() const
{
  try {
    (void)m_document.headMotion(m_document.referenceMarkers());
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

void HeadStabilizedViewAction::followReferenceMarkers()
{
  if (m_view.headReference().empty())
    return;
  if (m_document.referenceMarkers().size() >= 3 && headPoseProblem().isEmpty()) {
    m_view.setHeadReference(m_document.referenceMarkers());  // the views dropped the old indices
    return;
  }
  m_view.setHeadReference({});
  emit message(tr("3D view back in the lab frame: the reference markers cannot carry a head pose"),
               2 * kStatusMessageMs);
}

} // namespace mocap::ui
