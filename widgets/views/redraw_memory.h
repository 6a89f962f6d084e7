#pragma once

namespace mocap::ui {

/// Keeps the memory that redrawing frees for the next redraw. Each repaint of a window that
/// holds a 3D view copies the window's image (4 MB at 1280×800) twice on its way to the screen;
/// glibc's default, adaptive thresholds hand such blocks back to the kernel when they are freed,
/// so every repaint faulted in and zeroed fresh pages: 39 % of the UI thread's time while the
/// timeline was scrubbed. Blocks up to 32 MB now come from the heap, and up to 256 MB free at its
/// top stay mapped. Call once, first thing in main (glibc only; elsewhere it does nothing).
void keepRedrawMemoryMapped();

} // namespace mocap::ui
