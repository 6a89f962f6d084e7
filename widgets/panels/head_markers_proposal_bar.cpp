#include "panels/head_markers_proposal_bar.h"

#include "document/take_document.h"

#include <QColor>
#include <QHBoxLayout>
#include <QLabel>
#include <QPalette>
#include <QPushButton>
#include <QStringList>
#include <QToolButton>

namespace mocap::ui {

HeadMarkersProposalBar::HeadMarkersProposalBar(const TakeDocument& document, QWidget* parent)
    : QFrame(parent), m_document(document)
{
  setObjectName(QStringLiteral("headMarkersProposalBar"));
  setFrameShape(QFrame::StyledPanel);
  setAutoFillBackground(true);
  QPalette colours = palette();  // a message bar's pale yellow: noticed, not alarming
  colours.setColor(QPalette::Window, QColor(255, 243, 205));
  colours.setColor(QPalette::WindowText, QColor(60, 45, 0));
  setPalette(colours);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(8, 4, 4, 4);
  m_text = new QLabel(this);
  m_text->setObjectName(QStringLiteral("headMarkersProposal"));
  m_text->setWordWrap(true);
  m_text->setToolTip(tr("The take names no head markers (root… or head…) and has none saved: these move together "
                        "as one rigid body. Nothing uses them until you accept them."));
  auto* accept = new QPushButton(tr("Accept"), this);
  accept->setObjectName(QStringLiteral("acceptHeadMarkers"));
  accept->setToolTip(tr("Use these markers for head stabilization, the head-stabilized view, layout planning and "
                        "the face mesh, and save them with the take (undoable)"));
  auto* choose = new QPushButton(tr("Choose…"), this);
  choose->setObjectName(QStringLiteral("chooseHeadMarkers"));
  choose->setToolTip(tr("Choose the head markers yourself (Marker ▸ Reference Markers…)"));
  auto* close = new QToolButton(this);
  close->setText(QStringLiteral("×"));
  close->setAutoRaise(true);
  close->setToolTip(tr("Not now: no head markers for this take"));
  layout->addWidget(m_text, 1);
  layout->addWidget(accept);
  layout->addWidget(choose);
  layout->addWidget(close);
  connect(accept, &QPushButton::clicked, this, [this] {
    const std::vector<Eigen::Index> markers = m_shown;
    answer();
    emit acceptRequested(markers);
  });
  connect(choose, &QPushButton::clicked, this, [this] {
    answer();
    emit chooseRequested();
  });
  connect(close, &QToolButton::clicked, this, &HeadMarkersProposalBar::answer);
  connect(&document, &TakeDocument::takeReset, this, &HeadMarkersProposalBar::refresh);
  connect(&document, &TakeDocument::referenceMarkersChanged, this, [this] {
    if (!m_document.referenceMarkers().empty())
      answer();  // chosen elsewhere: the question is answered
  });
  refresh();
}

QString HeadMarkersProposalBar::text() const
{
  return m_text->text();
}

void HeadMarkersProposalBar::refresh()
{
  m_shown = m_document.referenceMarkers().empty() ? m_document.proposedReferenceMarkers()
                                                  : std::vector<Eigen::Index>{};
  QStringList labels;
  for (const Eigen::Index m : m_shown)
    labels << QString::fromStdString(m_document.take().label(m));
  m_text->setText(tr("Head markers guessed: %1").arg(labels.join(QStringLiteral(", "))));
  setVisible(!m_shown.empty());
}

void HeadMarkersProposalBar::answer()
{
  m_shown.clear();
  hide();
}

} // namespace mocap::ui
