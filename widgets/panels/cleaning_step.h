#pragma once

#include "mocap/base/job_control.h"
#include "mocap/cleaning/clean_pipeline.h"
#include "mocap/model/sample_patch.h"

#include <QComboBox>
#include <QString>
#include <QWidget>

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

class QComboBox;

namespace mocap::ui {

/// A line a step lists for review (e.g. a gap left open and why), pointing at one sample.
struct ReviewNote
{
  Eigen::Index marker = 0;
  Eigen::Index frame = 0;
  QString text;
};

/// What a cleaning step proposes for a take: the patches Apply would push, samples to flag for
/// review, and a one-line summary.
struct StepResult
{
  std::vector<SamplePatch> patches;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> flags;  ///< (marker, frame)
  QString summary;
  /// True for a detection: its flags become the document's flags (kept on every tab until the
  /// next detection). Other steps leave the document's flags alone.
  bool detection = false;
  std::vector<ReviewNote> notes;  ///< shown by the step (showResult)
};

/// What the panel's "Selected markers only" / "Selected frame range only" limit a step to, so a
/// step's summary counts what Apply would change.
struct StepScope
{
  bool markersOnly = false;
  std::vector<Eigen::Index> markers;  ///< sorted; meaningful when markersOnly
  bool rangeOnly = false;
  Eigen::Index first = 0, last = -1;  ///< the frame range; empty when first > last

  [[nodiscard]] bool hasMarker(Eigen::Index marker) const;
};

inline bool StepScope::hasMarker(Eigen::Index marker) const
{
  return !markersOnly || std::binary_search(markers.begin(), markers.end(), marker);
}

/// The samples and the distinct markers `patches` hold. O(total patch size + #patches log #patches).
struct PatchCounts
{
  int samples = 0;
  int markers = 0;
};
[[nodiscard]] PatchCounts countPatches(const std::vector<SamplePatch>& patches);
/// "415 samples repaired on 37 markers" from `one` ("1 sample repaired") and `many` ("%1 samples
/// repaired"): singular and plural spelled out, as the source language has no catalogue. O(1).
[[nodiscard]] QString samplesOnMarkers(const PatchCounts& counts, const QString& one, const QString& many);

/// Makes `combo`'s own tooltip its current item's (Qt::ToolTipRole), so the chosen method says
/// what it does without opening the list. O(1) per change.
void tipFollowsCurrentItem(QComboBox& combo);

/// A computation of a step with the parameters it had when job() was called; runs on a worker
/// thread on its own copy of the take, so it must not touch widgets. It passes the JobControl to
/// the core step, which reports progress and stops (JobCancelled) when the panel cancels.
using StepJob = std::function<StepResult(const Take&, const JobControl&)>;

/// Selects the entry of `box` whose data is `value` (a method enum); leaves the box alone when it
/// offers none (a preset naming a method this panel lacks keeps the panel's choice).
inline void selectMethod(QComboBox& box, int value)
{
  if (const int index = box.findData(value); index >= 0)
    box.setCurrentIndex(index);
}

/// One tab of the cleaning panel: parameters for one core method. Emits changed() whenever a
/// parameter changes, so the panel can refresh the live preview.
class CleaningStep : public QWidget
{
  Q_OBJECT

public:
  using QWidget::QWidget;

  /// The step's title for undo texts, presets and the tab's tooltip ("Stabilize head").
  [[nodiscard]] virtual QString title() const = 0;
  /// The tab's word, whole: the four tabs fit side by side in the dock of the first window on a
  /// 1280×800 screen (a longer title was cut to "Sta" behind the scroll arrows). The title by default.
  [[nodiscard]] virtual QString tabTitle() const { return title(); }
  [[nodiscard]] virtual StepJob job() const = 0;
  /// The patches Apply pushes, given the last result (a step may let the user reject some).
  [[nodiscard]] virtual std::vector<SamplePatch> patchesToApply(const Take& take, const StepResult& result) const
  {
    (void)take;
    return result.patches;
  }
  /// True for a step that changes the whole take or nothing (head stabilization is a change of
  /// coordinates): the panel's "selected markers only" and "frame range only" do not apply to it.
  [[nodiscard]] virtual bool wholeTake() const { return false; }
  /// Shows a finished result (e.g. a list of flags to review). Called on the UI thread.
  virtual void showResult(const StepResult& result) { (void)result; }
  /// Told the patches Apply pushed (before the push changes the take). Called on the UI thread.
  virtual void applied(const std::vector<SamplePatch>& patches) { (void)patches; }
  /// What Apply did, in words, counted from the patches it pushed (`applied`) and the result they
  /// came from, e.g. "415 samples changed on 37 markers". The panel shows it until a setting or
  /// the take changes. Called on the UI thread before the push. O(total patch size).
  [[nodiscard]] virtual QString appliedSummary(const std::vector<SamplePatch>& applied, const StepResult& result) const;
  /// Puts this step's current parameters into `options` (File ▸ Save Cleaning Preset…, the
  /// preset `mocap batch --preset` reads). A step that is no pipeline step leaves it alone.
  virtual void addToPreset(CleanOptions& options) const { (void)options; }
  /// Sets this step's parameters from a preset's (File ▸ Load Cleaning Preset…): the preview
  /// shows them, the take is untouched until Apply. Returns false when the preset turns this
  /// step off (the step keeps its parameters; the panel says so). A step with nothing in presets
  /// returns true.
  virtual bool loadPreset(const CleanOptions& options)
  {
    (void)options;
    return true;
  }
  /// Set by the panel before job() and patchesToApply().
  void setScope(StepScope scope) { m_scope = std::move(scope); }
  [[nodiscard]] const StepScope& scope() const { return m_scope; }

signals:
  void changed();

private:
  StepScope m_scope;
};

} // namespace mocap::ui
