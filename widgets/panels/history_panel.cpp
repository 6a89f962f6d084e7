#include "panels/history_panel.h"

#include "document/take_document.h"

#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTreeWidget>
#include <QUndoView>
#include <QVBoxLayout>

namespace mocap::ui {

namespace {

QString framesText(const ProcessingStep& step)
{
  if (step.lastFrame < step.firstFrame)
    return HistoryPanel::tr("all");
  return QStringLiteral("%1–%2").arg(step.firstFrame).arg(step.lastFrame);
}

QString markersText(const ProcessingStep& step)
{
  if (step.markers.empty())
    return HistoryPanel::tr("all");
  QStringList labels;
  for (const std::string& label : step.markers)
    labels << QString::fromStdString(label);
  return labels.join(QStringLiteral(", "));
}

QString parametersText(const ProcessingStep& step)
{
  QStringList parts;
  for (const auto& [name, value] : step.parameters)
    parts << QStringLiteral("%1 %2").arg(QString::fromStdString(name), QString::fromStdString(value));
  return parts.join(QStringLiteral(", "));
}

} // namespace

HistoryPanel::HistoryPanel(TakeDocument& document, QWidget* parent) : QWidget(parent), m_document(document)
{
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* splitter = new QSplitter(Qt::Vertical, this);
  auto* top = new QWidget(splitter);
  auto* topLayout = new QVBoxLayout(top);
  topLayout->setContentsMargins(4, 4, 4, 0);
  topLayout->addWidget(new QLabel(tr("Processing history (saved with the take)"), top));
  m_steps = new QTreeWidget(top);
  m_steps->setObjectName(QStringLiteral("processingHistory"));
  m_steps->setHeaderLabels({tr("Step"), tr("Parameters"), tr("Markers"), tr("Frames"), tr("Samples"), tr("Time")});
  m_steps->setRootIsDecorated(false);
  m_steps->setAlternatingRowColors(true);
  m_steps->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
  topLayout->addWidget(m_steps);
  auto* bottom = new QWidget(splitter);
  auto* bottomLayout = new QVBoxLayout(bottom);
  bottomLayout->setContentsMargins(4, 0, 4, 4);
  bottomLayout->addWidget(new QLabel(tr("Undo history (this session)"), bottom));
  m_undoView = new QUndoView(document.undoStack(), bottom);
  m_undoView->setEmptyLabel(tr("<opened take>"));
  bottomLayout->addWidget(m_undoView);
  layout->addWidget(splitter);
  connect(&document, &TakeDocument::historyChanged, this, &HistoryPanel::rebuild);
  rebuild();
}

void HistoryPanel::rebuild()
{
  m_steps->clear();
  for (const ProcessingStep& step : m_document.take().history()) {
    auto* item = new QTreeWidgetItem(m_steps);
    item->setText(0, QString::fromStdString(step.operation));
    item->setText(1, parametersText(step));
    item->setText(2, markersText(step));
    item->setText(3, framesText(step));
    item->setText(4, QString::number(step.samples));
    item->setText(5, QString::fromStdString(step.time));
    item->setToolTip(0, tr("%1 by %2 at %3").arg(QString::fromStdString(step.operation),
                                                QString::fromStdString(step.tool), QString::fromStdString(step.time)));
    item->setToolTip(1, parametersText(step));
    item->setToolTip(2, markersText(step));
  }
  if (m_steps->topLevelItemCount() > 0)
    m_steps->scrollToItem(m_steps->topLevelItem(m_steps->topLevelItemCount() - 1));
}

} // namespace mocap::ui
