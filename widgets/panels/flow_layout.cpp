#include "panels/flow_layout.h"

#include <QWidget>

#include <algorithm>

namespace mocap::ui {

FlowLayout::FlowLayout(QWidget* parent) : QLayout(parent)
{
  if (!parent)
    setContentsMargins(0, 0, 0, 0);
}

FlowLayout::~FlowLayout()
{
  while (QLayoutItem* item = FlowLayout::takeAt(0))
    delete item;
}

void FlowLayout::addItem(QLayoutItem* item)
{
  m_items.append(item);
}

int FlowLayout::count() const
{
  return static_cast<int>(m_items.size());
}

QLayoutItem* FlowLayout::itemAt(int index) const
{
  return m_items.value(index);
}

QLayoutItem* FlowLayout::takeAt(int index)
{
  return index >= 0 && index < m_items.size() ? m_items.takeAt(index) : nullptr;
}

Qt::Orientations FlowLayout::expandingDirections() const
{
  return {};
}

bool FlowLayout::hasHeightForWidth() const
{
  return true;
}

int FlowLayout::heightForWidth(int width) const
{
  return arrange(QRect(0, 0, width, 0), false);
}

QSize FlowLayout::minimumSize() const
{
  QSize size;
  for (const QLayoutItem* item : m_items)
    if (!item->isEmpty())
      size = size.expandedTo(item->minimumSize());
  const QMargins margins = contentsMargins();
  return size + QSize(margins.left() + margins.right(), margins.top() + margins.bottom());
}

QSize FlowLayout::sizeHint() const
{
  // All on one line, as wide as there is room for.
  int width = 0, height = 0;
  for (const QLayoutItem* item : m_items) {
    if (item->isEmpty())
      continue;
    width += (width > 0 ? gap() : 0) + item->sizeHint().width();
    height = std::max(height, item->sizeHint().height());
  }
  const QMargins margins = contentsMargins();
  return {width + margins.left() + margins.right(), height + margins.top() + margins.bottom()};
}

void FlowLayout::setGeometry(const QRect& rect)
{
  QLayout::setGeometry(rect);
  (void)arrange(rect, true);
}

int FlowLayout::gap() const
{
  const int spacing = QLayout::spacing();
  return spacing >= 0 ? spacing : 6;
}

int FlowLayout::arrange(const QRect& rect, bool apply) const
{
  const QMargins margins = contentsMargins();
  const QRect area = rect.marginsRemoved(margins);
  int x = area.x(), y = area.y(), lineHeight = 0;
  for (QLayoutItem* item : m_items) {
    if (item->isEmpty())
      continue;
    const QSize hint = item->sizeHint().boundedTo(QSize(area.width(), item->sizeHint().height()))
                           .expandedTo(item->minimumSize());
    if (x > area.x() && x + hint.width() > area.right() + 1) {  // the next line
      x = area.x();
      y += lineHeight + gap();
      lineHeight = 0;
    }
    if (apply)
      item->setGeometry(QRect(QPoint(x, y), hint));
    x += hint.width() + gap();
    lineHeight = std::max(lineHeight, hint.height());
  }
  return y + lineHeight - rect.y() + margins.bottom();
}

} // namespace mocap::ui
