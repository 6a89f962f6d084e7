#include "panels/reference_markers_row.h"

#include "document/take_document.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStringList>

namespace mocap::ui {

ReferenceMarkersRow::ReferenceMarkersRow(const TakeDocument& document, const QString& purpose, QWidget* parent)
    : QWidget(parent), m_document(document)
{
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  m_labels = new QLabel(this);
  m_labels->setObjectName(QStringLiteral("referenceMarkers"));
  m_labels->setWordWrap(true);
  m_labels->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_labels->setToolTip(purpose + QLatin1Char('\n') + tr("One set per take, chosen in Marker ▸ Reference Markers…"));
  m_edit = new QPushButton(tr("Edit…"), this);
  m_edit->setToolTip(tr("Choose the reference markers (Marker ▸ Reference Markers…)"));
  layout->addWidget(m_labels, 1);
  layout->addWidget(m_edit, 0, Qt::AlignTop);
  connect(m_edit, &QPushButton::clicked, this, &ReferenceMarkersRow::editRequested);
  connect(&document, &TakeDocument::takeReset, this, &ReferenceMarkersRow::refresh);
  connect(&document, &TakeDocument::referenceMarkersChanged, this, &ReferenceMarkersRow::refresh);
  refresh();
}

QString ReferenceMarkersRow::text() const
{
  return m_labels->text();
}

void ReferenceMarkersRow::refresh()
{
  QStringList labels;
  for (const std::string& label : m_document.referenceLabels())
    labels << QString::fromStdString(label);
  if (labels.isEmpty())
    m_labels->setText(tr("none (head motion is not removed)"));
  else
    m_labels->setText(tr("%1 (%2)").arg(labels.join(QStringLiteral(", "))).arg(labels.size()));
  m_edit->setEnabled(m_document.hasTake());
}

} // namespace mocap::ui
