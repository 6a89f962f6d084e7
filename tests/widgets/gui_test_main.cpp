// GoogleTest main for GUI tests: one QApplication with the surface format VTK needs.
// Run under Xvfb (scripts/test.sh does): the offscreen platform has no OpenGL for the 3D view.
#include "views/vtk_viewport.h"

#include <QApplication>
#include <QStandardPaths>
#include <QSurfaceFormat>

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  if (::testing::GTEST_FLAG(list_tests))
    return RUN_ALL_TESTS();  // listing (ctest discovery) needs no display
  QSurfaceFormat::setDefaultFormat(mocap::ui::VtkViewport::defaultFormat());
  QApplication::setOrganizationName(QStringLiteral("MocapStudioTests"));
  QApplication::setApplicationName(QStringLiteral("Mocap Studio GUI tests"));
  QStandardPaths::setTestModeEnabled(true);  // settings and recovery files away from the user's
  QApplication app(argc, argv);
  return RUN_ALL_TESTS();
}
