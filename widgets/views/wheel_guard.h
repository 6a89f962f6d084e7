#pragma once

#include <QObject>

namespace mocap::ui {

/// Keeps the mouse wheel from changing a combo box, spin box or slider that it merely passes
/// over while scrolling a dock: inside a scroll area, such a widget takes the wheel only when
/// it has the keyboard focus; otherwise the scroll area scrolls. Install once on the application.
class WheelGuard final : public QObject
{
  Q_OBJECT

public:
  using QObject::QObject;
  /// Installs one guard on the application (again: nothing happens).
  static void install();

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;
};

} // namespace mocap::ui
