#pragma once

#include "mocap/base/job_control.h"

#include <QString>

#include <functional>

class QWidget;

namespace mocap::ui {

/// Runs `work` on a worker thread while the UI thread keeps serving events (paint, timers; user
/// input waits): when the work takes longer than 0.4 s a window-modal progress dialog appears, with a time estimate and Cancel
/// (Esc), which stops the work at its next checkpoint. Returns false when cancelled; rethrows
/// what `work` threw. `work` must not touch widgets; it runs on data the caller owns until the
/// call returns (the call waits for the worker to end).
bool runJob(QWidget* parent, const QString& label, const std::function<void(const JobControl&)>& work);

/// True while a runJob call is running its work (a window should not close then). O(1).
[[nodiscard]] bool jobRunning();

} // namespace mocap::ui
