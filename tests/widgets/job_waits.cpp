#include "job_waits.h"

#include "document/job_runner.h"
#include "panels/cleaning_panel.h"
#include "panels/gap_list_panel.h"

#include <QElapsedTimer>
#include <QSignalSpy>

#include <gtest/gtest.h>

namespace mocap::test {

bool waitUntil(const ui::JobRunner& runner, const std::function<bool()>& done, int timeoutMs)
{
  QElapsedTimer clock;
  clock.start();
  while (!done()) {
    if (clock.elapsed() > timeoutMs)
      return false;
    QSignalSpy finished(&runner, &ui::JobRunner::finished);
    (void)finished.wait(50);
  }
  return true;
}

bool waitForJob(const ui::JobRunner& runner, int timeoutMs)
{
  return waitUntil(runner, [&runner] { return !runner.running(); }, timeoutMs);
}

void waitForPreview(ui::CleaningPanel& panel)
{
  const bool shown = waitUntil(panel.jobs(), [&panel] {
    if (panel.previewReady())
      return true;
    if (!panel.busy())
      panel.refresh();
    return false;
  });
  EXPECT_TRUE(shown) << "no preview within the time limit: " << panel.statusText().toStdString();
}

void waitUntilIdle(ui::GapListPanel& panel)
{
  EXPECT_TRUE(waitUntil(panel.jobs(), [&panel] { return !panel.busy(); }))
      << "the Gaps dock is still busy: " << panel.statusText().toStdString();
}

} // namespace mocap::test
