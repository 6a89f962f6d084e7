#pragma once

#include "mocap/sample_patch.h"

#include <QString>
#include <QWidget>

#include <functional>
#include <utility>
#include <vector>

namespace mocap::ui {

/// What a cleaning step proposes for a take: the patches Apply would push, samples to flag for
/// review, and a one-line summary.
struct StepResult
{
  std::vector<SamplePatch> patches;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> flags;  ///< (marker, frame)
  QString summary;
};

/// A computation of a step with the parameters it had when job() was called; runs on a worker
/// thread on its own copy of the take, so it must not touch widgets.
using StepJob = std::function<StepResult(const Take&)>;

/// One tab of the cleaning panel: parameters for one core method. Emits changed() whenever a
/// parameter changes, so the panel can refresh the live preview.
class CleaningStep : public QWidget
{
  Q_OBJECT

public:
  using QWidget::QWidget;

  /// The step's title for tabs and undo texts ("Fill gaps").
  [[nodiscard]] virtual QString title() const = 0;
  [[nodiscard]] virtual StepJob job() const = 0;
  /// The patches Apply pushes, given the last result (a step may let the user reject some).
  [[nodiscard]] virtual std::vector<SamplePatch> patchesToApply(const Take& take, const StepResult& result) const
  {
    (void)take;
    return result.patches;
  }
  /// True for a step that changes the whole take or nothing (head stabilisation is a change of
  /// coordinates): the panel's "selected markers only" and "frame range only" do not apply to it.
  [[nodiscard]] virtual bool wholeTake() const { return false; }
  /// Shows a finished result (e.g. a list of flags to review). Called on the UI thread.
  virtual void showResult(const StepResult& result) { (void)result; }

signals:
  void changed();
};

} // namespace mocap::ui
