// The cleaning steps one at a time: mocap.detect_spikes, fill_gaps, smooth and stabilize. Each is
// `mocap clean` with only that step on (the same preset reader, pipeline, history and report), so
// a step from Python gives the samples and the report section `mocap clean --fill off --smooth off
// ...` gives. On a selection of markers or frames (markers=, frames=) a step changes only the
// samples in it, as the studio's cleaning panel applies a step to a selection.

#include "bindings.h"
#include "clean_options.h"
#include "python_job.h"
#include "step_selection.h"

#include "mocap/base/error.h"
#include "mocap/batch/clean_run.h"
#include "mocap/model/gaps.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/provenance.h"
#include "mocap/model/sample_patch.h"
#include "mocap/model/take.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace mocap::python {

namespace {

/// A preset that runs only `step` (spikes, fill, smooth or stabilize) with `options`.
py::dict onlyStep(const char* step, const py::dict& options)
{
  py::dict preset;
  for (const char* other : {"spikes", "fill", "smooth"})
    preset[other] = py::dict(py::arg("method") = "off");
  preset[step] = options;
  return preset;
}

/// `options` with `key` set to `value` unless that is None.
py::dict with(py::dict options, const char* key, const py::object& value)
{
  if (!value.is_none())
    options[key] = value;
  return options;
}

/// The step's section of `mocap clean --report`, with the take's valid fraction after it and the
/// model outputs it left untouched.
py::dict stepReport(const py::dict& report, const char* step)
{
  auto section = report[step].cast<py::dict>();
  section["valid_fraction"] = report["valid_fraction"];
  section["model_outputs"] = report["model_outputs"];
  return section;
}

CleanOptions stepOptions(const char* step, const py::dict& options)
{
  return parseCleanOptions(onlyStep(step, options), std::string("mocap ") + step + " options");
}

/// The single step `options` names applied to the selection: its patches worked out on the whole
/// take by `patches(job)` (with the GIL released, Ctrl+C honoured), kept inside the selection and
/// applied, and the history step recorded for the whole take narrowed to the selection. `report`
/// holds what the step found; its sample count is set here through `samples`.
template <typename Patches>
py::dict applySelected(Take& take, const CleanOptions& options, const StepSelection& selection, CleanReport& report,
                       Eigen::Index CleanReport::*samples, const char* step, const py::object& progress,
                       Patches&& patches)
{
  runReleased(progress, [&](const JobControl& job) {
    std::vector<SamplePatch> kept = selection.within(patches(job));
    report.*samples = sampleCount(kept);
    applyPatches(take, std::move(kept));
    report.modelOutputs = modelOutputPoints(take);
    recordCleanSteps(take, options, report, kCleanTool);
    selection.narrow(take.history().back(), take);
    return 0;
  });
  return stepReport(cleanReportDict(take, options, report), step);
}

/// The flags inside the selection (all without one).
std::vector<SpikeFlag> flagsWithin(std::vector<SpikeFlag> flags, const std::optional<StepSelection>& selection)
{
  if (selection)
    flags.erase(std::remove_if(flags.begin(), flags.end(),
                               [&](const SpikeFlag& f) { return !selection->holds(f.marker, f.frame); }),
                flags.end());
  return flags;
}

py::dict detectSpikesStep(Take& take, const py::object& method, bool repair,
                          const std::optional<std::vector<std::string>>& markers,
                          const std::optional<std::pair<long long, long long>>& frames, const py::object& progress,
                          const py::kwargs& options)
{
  const CleanOptions parsed = stepOptions("spikes", with(py::dict(options), "method", method));
  const std::optional<StepSelection> selection = StepSelection::of(take, markers, frames);
  if (repair && !selection)
    return stepReport(cleanAndReport(take, parsed, progress), "spikes");
  CleanReport report;
  report.modelOutputs = modelOutputPoints(take);
  std::vector<SpikeFlag> all = runReleased(progress, [&](const JobControl& job) {
    return detectSpikes(take, *parsed.spikes, job);
  });
  report.spikes = flagsWithin(all, selection);
  if (!repair)
    return stepReport(cleanReportDict(take, parsed, report), "spikes");
  // Repaired as the whole take's repair would (blocks across the selection's border included),
  // then kept inside it, as the studio applies a selection.
  return applySelected(take, parsed, *selection, report, &CleanReport::repairedSamples, "spikes", py::none(),
                       [&](const JobControl&) { return replaceSpikes(take, all); });
}

py::dict fillGapsOf(Take& take, const py::object& method, const py::object& maxGap,
                    const std::optional<std::vector<std::string>>& markers,
                    const std::optional<std::pair<long long, long long>>& frames, const py::object& progress,
                    const py::kwargs& options)
{
  const CleanOptions parsed =
      stepOptions("fill", with(with(py::dict(options), "method", method), "max_gap_frames", maxGap));
  const std::optional<StepSelection> selection = StepSelection::of(take, markers, frames);
  if (!selection)
    return stepReport(cleanAndReport(take, parsed, progress), "fill");
  FillOptions fill = *parsed.fill;
  fill.fillAnyway = selection->markers;  // a marker asked for by name is meant
  CleanReport report;
  return applySelected(take, parsed, *selection, report, &CleanReport::filledSamples, "fill", progress,
                       [&](const JobControl& job) {
                         std::vector<Gap> gaps;
                         for (const Gap& gap : findGaps(take))
                           if (selection->overlaps(gap))
                             gaps.push_back(gap);
                         FillResult filled = fillGaps(take, gaps, fill, job);
                         report.gaps = std::move(filled.gaps);
                         return std::move(filled.patches);
                       });
}

py::dict smoothStep(Take& take, const py::object& method, const std::optional<std::vector<std::string>>& markers,
                    const std::optional<std::pair<long long, long long>>& frames, const py::object& progress,
                    const py::kwargs& options)
{
  const CleanOptions parsed = stepOptions("smooth", with(py::dict(options), "method", method));
  const std::optional<StepSelection> selection = StepSelection::of(take, markers, frames);
  if (!selection)
    return stepReport(cleanAndReport(take, parsed, progress), "smooth");
  CleanReport report;
  return applySelected(take, parsed, *selection, report, &CleanReport::smoothedSamples, "smooth", progress,
                       [&](const JobControl& job) { return smoothTake(take, *parsed.smooth, job); });
}

py::dict stabilize(Take& take, std::optional<std::vector<std::string>> markers, bool keepStabilized)
{
  if (!markers) {
    markers = headMarkers(take);
    if (markers->empty())
      throw InvalidArgument("the take has no head markers saved with it; name them: "
                            "stabilize(take, markers=[\"head1\", \"head2\", \"head3\"])");
  }
  py::dict step;
  step["markers"] = *markers;
  step["keep_stabilized"] = keepStabilized;
  return stepReport(cleanAndReport(take, stepOptions("stabilize", step)), "stabilize");
}

} // namespace

void bindCleaningSteps(py::module_& m)
{
  m.def("detect_spikes", &detectSpikesStep, py::arg("take"), py::arg("method") = py::none(), py::arg("repair") = true,
        py::arg("markers") = py::none(), py::arg("frames") = py::none(), py::arg("progress") = py::none(),
        "Finds spikes as `mocap clean --fill off --smooth off` does and, with repair (the default), "
        "replaces them in place (recorded in the history). Options as the preset's \"spikes\": method "
        "('robust' or 'paper'), factor, threshold, noise_floor (mm), max_passes; left out: mocap clean's "
        "defaults. markers (labels) and frames=(first, last), as the take numbers them, limit the flags "
        "reported and the samples repaired to that selection (the repair worked out as on the whole take). "
        "Returns the report's \"spikes\" section (method, count, repaired_samples, flagged: "
        "[{marker, frame}], frames as the take numbers them) with valid_fraction and model_outputs. progress(fraction) and Ctrl+C as mocap.clean.");
  m.def("fill_gaps", &fillGapsOf, py::arg("take"), py::arg("method") = py::none(), py::arg("max_gap") = py::none(),
        py::arg("markers") = py::none(), py::arg("frames") = py::none(), py::arg("progress") = py::none(),
        "Fills gaps in place as `mocap clean --spikes off --smooth off` does. Options as the preset's "
        "\"fill\": method ('auto', 'linear', 'spline', 'guenter', 'lin-ouhyoung', 'zhang3', 'zhang-n', "
        "'rigid', 'pca'), max_gap (frames; 0: max_gap_seconds), max_gap_seconds, extrapolate, "
        "min_valid_fraction, neighbours. markers (labels) limits the fill to those markers' gaps, filled "
        "whatever their valid fraction; frames=(first, last), as the take numbers them, to the gaps "
        "overlapping that range, changing only samples within it. Returns the report's \"fill\" section "
        "(filled and unfilled gaps with the cause and reason) with valid_fraction and model_outputs. progress(fraction) and Ctrl+C as mocap.clean (a stopped step leaves the take as it was).");
  m.def("smooth", &smoothStep, py::arg("take"), py::arg("method") = py::none(), py::arg("markers") = py::none(),
        py::arg("frames") = py::none(), py::arg("progress") = py::none(),
        "Smooths every valid run in place as `mocap clean --spikes off --fill off` does. Options as the "
        "preset's \"smooth\": method ('gcvspl', 'bspline', 'butterworth', 'savgol'), degree, knot_spacing, "
        "cutoff_hz, winter_cutoff, gcvspl_mode, gcvspl_degree, error_variance, savgol_window, savgol_degree. "
        "markers (labels) and frames=(first, last), as the take numbers them, change only those samples "
        "(smoothed as on the whole take). Returns the report's \"smooth\" section with valid_fraction and "
        "model_outputs. progress(fraction) and Ctrl+C as mocap.clean.");
  m.def("stabilize", &stabilize, py::arg("take"), py::arg("markers") = py::none(), py::arg("keep_stabilized") = true,
        "Removes the head's rigid motion, estimated from head-mounted markers (labels; None: the ones saved "
        "with the take), as `mocap clean --stabilize LABELS --keep-stabilized` does: the markers are left "
        "in head space. Returns the report's \"stabilize\" section (markers, unknown_head_poses, "
        "kept_stabilized) with valid_fraction and model_outputs.");
}

} // namespace mocap::python
