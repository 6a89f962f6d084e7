#pragma once

#include "main_window.h"

#include <QApplication>
#include <QSettings>
#include <QElapsedTimer>
#include <QTimer>

#include <gtest/gtest.h>

#include <functional>
#include <memory>

namespace mocap::test {

/// The studio as a technician starts it on the bundled sample take: no remembered settings, a
/// fixed size, shown, exposed and (where the display allows) active, so shortcuts work.
/// Returns nullptr after a test failure when the window or the take did not come up.
[[nodiscard]] std::unique_ptr<studio::MainWindow> openSampleWindow(int width = 1280, int height = 800);

/// A test fixture on openSampleWindow(1280, 900) that forgets the settings it changed.
class SampleWindowTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    window = openSampleWindow(1280, 900);
    ASSERT_NE(window, nullptr);
  }
  void TearDown() override { QSettings().clear(); }

  ui::TakeDocument& doc() { return window->document(); }

  std::unique_ptr<studio::MainWindow> window;
};

/// Runs `act` on the first modal widget of type T to come up, polling every 10 ms for up to
/// 10 s: for a dialog opened after work the UI thread waits on (a zero timer would fire then,
/// before the dialog is there). `act` must close the dialog.
template <typename T>
void whenModal(std::function<void(T*)> act)
{
  auto* poll = new QTimer(qApp);
  auto clock = std::make_shared<QElapsedTimer>();
  clock->start();
  QObject::connect(poll, &QTimer::timeout, poll, [poll, clock, act = std::move(act)] {
    if (auto* modal = qobject_cast<T*>(QApplication::activeModalWidget())) {
      poll->deleteLater();
      poll->stop();
      act(modal);
    } else if (clock->elapsed() > 10000) {
      poll->deleteLater();
      poll->stop();
    }
  });
  poll->start(10);
}

} // namespace mocap::test
