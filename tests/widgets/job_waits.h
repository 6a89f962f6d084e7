#pragma once
// Waiting for the studio's background jobs in a test: on the job runner's finished() signal, with
// the event loop served meanwhile (a debounce timer may start the next job). The studio itself
// never waits on its jobs.

#include <functional>

namespace mocap::ui {
class CleaningPanel;
class GapListPanel;
class JobRunner;
} // namespace mocap::ui

namespace mocap::test {

/// Serves the event loop until `done()` holds, woken by the runner's finished() or every 50 ms;
/// false after `timeoutMs`.
[[nodiscard]] bool waitUntil(const ui::JobRunner& runner, const std::function<bool()>& done, int timeoutMs = 300000);
/// Until the runner has no job (delivered, failed or cancelled); false on timeout.
[[nodiscard]] bool waitForJob(const ui::JobRunner& runner, int timeoutMs = 300000);
/// Until the panel shows the preview of its latest request; a stale preview with nothing running
/// (hidden, live preview off, a debounce pending) is computed now. Fails the test on timeout.
void waitForPreview(ui::CleaningPanel& panel);
/// Until the Gaps dock has nothing running or pending (preview, fill). Fails the test on timeout.
void waitUntilIdle(ui::GapListPanel& panel);

} // namespace mocap::test
