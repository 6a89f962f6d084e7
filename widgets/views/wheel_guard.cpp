#include "views/wheel_guard.h"

#include <QAbstractScrollArea>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QSlider>

namespace mocap::ui {

namespace {

QAbstractScrollArea* enclosingScrollArea(QWidget* widget)
{
  for (QWidget* w = widget->parentWidget(); w; w = w->parentWidget())
    if (auto* area = qobject_cast<QAbstractScrollArea*>(w))
      return area;
  return nullptr;
}

bool isValueWidget(QObject* object)
{
  return qobject_cast<QComboBox*>(object) || qobject_cast<QAbstractSpinBox*>(object) || qobject_cast<QSlider*>(object);
}

} // namespace

void WheelGuard::install()
{
  if (!qApp || qApp->findChild<WheelGuard*>(QString(), Qt::FindDirectChildrenOnly))
    return;
  qApp->installEventFilter(new WheelGuard(qApp));
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event)
{
  if (!isValueWidget(watched))
    return false;
  auto* widget = static_cast<QWidget*>(watched);
  // Wheel focus would give the widget the focus before the wheel event reaches this filter.
  if (event->type() == QEvent::Polish && widget->focusPolicy() == Qt::WheelFocus)
    widget->setFocusPolicy(Qt::StrongFocus);
  if (event->type() != QEvent::Wheel)
    return false;
  if (widget->hasFocus())
    return false;
  QAbstractScrollArea* area = enclosingScrollArea(widget);
  if (!area)
    return false;
  QCoreApplication::sendEvent(area->viewport(), event);
  return true;
}

} // namespace mocap::ui
