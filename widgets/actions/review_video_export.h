#pragma once

#include <QString>

#include <functional>

class QWidget;

namespace mocap::ui {

struct ReviewSource;

/// File ▸ Export Review Video…: asks for the file, size and frames (the session's shown reference
/// video offered beside the view), then renders `source` with a progress dialog and Cancel; a
/// cancelled or failed export leaves no file, a failure is shown in a warning. Frames render on
/// the UI thread (the view's GL context is there), events served between them. What was written
/// or that nothing was goes to `message` (text, timeout in ms). O(frames × render).
void exportReviewVideo(const ReviewSource& source, QWidget& dialogParent,
                       const std::function<void(const QString&, int)>& message);

} // namespace mocap::ui
