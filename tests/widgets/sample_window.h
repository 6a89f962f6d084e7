#pragma once

#include "main_window.h"

#include <memory>

namespace mocap::test {

/// The studio as a technician starts it on the bundled sample take: no remembered settings, a
/// fixed size, shown, exposed and (where the display allows) active, so shortcuts work.
/// Returns nullptr after a test failure when the window or the take did not come up.
[[nodiscard]] std::unique_ptr<studio::MainWindow> openSampleWindow(int width = 1280, int height = 800);

} // namespace mocap::test
