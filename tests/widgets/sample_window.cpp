#include "sample_window.h"

#include "../core/test_support.h"

#include <QSettings>
#include <QTest>

#include <gtest/gtest.h>

namespace mocap::test {

std::unique_ptr<studio::MainWindow> openSampleWindow(int width, int height)
{
  QSettings().clear();  // no remembered layout or recent files from other runs
  auto window = std::make_unique<studio::MainWindow>();
  window->resize(width, height);
  window->show();
  if (!QTest::qWaitForWindowExposed(window.get())) {
    ADD_FAILURE() << "the studio window was not exposed";
    return nullptr;
  }
  window->activateWindow();  // shortcuts need the active window (Xvfb has no window manager)
  (void)QTest::qWaitForWindowActive(window.get());  // asserted only where a test needs it
  const QString error = window->openFile(QString::fromStdString(sampleTake().string()), true);
  if (!error.isEmpty()) {
    ADD_FAILURE() << "the sample take did not open: " << error.toStdString();
    return nullptr;
  }
  return window;
}

} // namespace mocap::test
