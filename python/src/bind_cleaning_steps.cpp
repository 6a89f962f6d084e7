// The cleaning steps one at a time: mocap.detect_spikes, fill_gaps, smooth and stabilize. Each is
// `mocap clean` with only that step on (the same preset reader, pipeline, history and report), so
// a step from Python gives the samples and the report section `mocap clean --fill off --smooth off
// ...` gives. fill_gaps on a selection of markers or frames fills the gaps in it as the studio's
// Gaps step does on a selection.

#include "bindings.h"
#include "clean_options.h"

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
#include <tuple>
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

/// Which gaps mocap.fill_gaps fills: those of `markers` (all when empty) overlapping frames
/// [first, last] (0-based) when ranged.
struct FillSelection
{
  std::vector<Eigen::Index> markers;
  bool ranged = false;
  Eigen::Index first = 0;
  Eigen::Index last = -1;

  [[nodiscard]] bool holds(const Gap& gap) const
  {
    const bool marker = markers.empty() || std::find(markers.begin(), markers.end(), gap.marker) != markers.end();
    return marker && (!ranged || (gap.firstFrame <= last && gap.firstFrame + gap.length - 1 >= first));
  }
};

/// `frames` = (first, last) as the take numbers them, both included, as 0-based indices.
std::pair<Eigen::Index, Eigen::Index> frameRange(const Take& take, const std::pair<long long, long long>& frames)
{
  const long long first = frames.first - take.firstFrame();
  const long long last = frames.second - take.firstFrame();
  if (first > last || first < 0 || last >= take.frameCount())
    throw InvalidArgument("frames (" + std::to_string(frames.first) + ", " + std::to_string(frames.second) +
                          ") must be a range (first, last) within the take's frames " +
                          std::to_string(take.firstFrame()) + "…" +
                          std::to_string(take.firstFrame() + take.frameCount() - 1));
  return {first, last};
}

/// Fills the selected gaps and records the step on the markers and frames it covered; samples
/// outside the range stay as they are (a gap across its border is filled up to it).
py::dict fillSelection(Take& take, const CleanOptions& options, const FillSelection& selection,
                       const std::vector<std::string>& labels)
{
  FillOptions fill = *options.fill;
  fill.fillAnyway = selection.markers;  // a marker asked for by name is meant
  CleanReport report;
  {
    const py::gil_scoped_release release;
    std::vector<Gap> gaps;
    for (const Gap& gap : findGaps(take))
      if (selection.holds(gap))
        gaps.push_back(gap);
    FillResult filled = fillGaps(take, gaps, fill);
    std::vector<SamplePatch> patches;
    for (SamplePatch& patch : filled.patches) {
      if (selection.ranged)
        patch = patchWithin(patch, selection.first, selection.last);
      report.filledSamples += static_cast<Eigen::Index>(patch.size());
      patches.push_back(std::move(patch));
    }
    applyPatches(take, std::move(patches));
    report.gaps = std::move(filled.gaps);
    report.modelOutputs = modelOutputPoints(take);
    recordCleanSteps(take, options, report, kCleanTool);
    ProcessingStep& step = take.history().back();
    step.markers = labels;
    if (selection.ranged) {
      step.firstFrame = take.firstFrame() + selection.first;
      step.lastFrame = take.firstFrame() + selection.last;
    }
  }
  return stepReport(cleanReportDict(take, options, report), "fill");
}

py::dict detectSpikesStep(Take& take, const py::object& method, bool repair, const py::kwargs& options)
{
  const CleanOptions parsed = stepOptions("spikes", with(py::dict(options), "method", method));
  if (repair)
    return stepReport(cleanAndReport(take, parsed), "spikes");
  CleanReport report;
  report.modelOutputs = modelOutputPoints(take);
  {
    const py::gil_scoped_release release;
    report.spikes = detectSpikes(take, *parsed.spikes);
  }
  return stepReport(cleanReportDict(take, parsed, report), "spikes");
}

py::dict fillGapsOf(Take& take, const py::object& method, const py::object& maxGap,
                    const std::optional<std::vector<std::string>>& markers,
                    const std::optional<std::pair<long long, long long>>& frames, const py::kwargs& options)
{
  const CleanOptions parsed =
      stepOptions("fill", with(with(py::dict(options), "method", method), "max_gap_frames", maxGap));
  if (!markers && !frames)
    return stepReport(cleanAndReport(take, parsed), "fill");
  FillSelection selection;
  if (markers)
    selection.markers = markerIndices(take, *markers);
  if (frames) {
    selection.ranged = true;
    std::tie(selection.first, selection.last) = frameRange(take, *frames);
  }
  return fillSelection(take, parsed, selection, markers ? *markers : std::vector<std::string>{});
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
        "Finds spikes as `mocap clean --fill off --smooth off` does and, with repair (the default), "
        "replaces them in place (recorded in the history). Options as the preset's \"spikes\": method "
        "('robust' or 'paper'), factor, threshold, noise_floor (mm), max_passes; left out: mocap clean's "
        "defaults. Returns the report's \"spikes\" section (method, count, repaired_samples, flagged: "
        "[{marker, frame}], frames as the take numbers them) with valid_fraction and model_outputs.");
  m.def("fill_gaps", &fillGapsOf, py::arg("take"), py::arg("method") = py::none(), py::arg("max_gap") = py::none(),
        py::arg("markers") = py::none(), py::arg("frames") = py::none(),
        "Fills gaps in place as `mocap clean --spikes off --smooth off` does. Options as the preset's "
        "\"fill\": method ('auto', 'linear', 'spline', 'guenter', 'lin-ouhyoung', 'zhang3', 'zhang-n', "
        "'rigid', 'pca'), max_gap (frames; 0: max_gap_seconds), max_gap_seconds, extrapolate, "
        "min_valid_fraction, neighbours. markers (labels) limits the fill to those markers' gaps, filled "
        "whatever their valid fraction; frames=(first, last), as the take numbers them, to the gaps "
        "overlapping that range, changing only samples within it. Returns the report's \"fill\" section "
        "(filled and unfilled gaps with the cause and reason) with valid_fraction and model_outputs.");
  m.def(
      "smooth",
      [](Take& take, const py::object& method, const py::kwargs& options) {
        return stepReport(cleanAndReport(take, stepOptions("smooth", with(py::dict(options), "method", method))),
                          "smooth");
      },
      py::arg("take"), py::arg("method") = py::none(),
      "Smooths every valid run in place as `mocap clean --spikes off --fill off` does. Options as the "
      "preset's \"smooth\": method ('gcvspl', 'bspline', 'butterworth', 'savgol'), degree, knot_spacing, "
      "cutoff_hz, winter_cutoff, gcvspl_mode, gcvspl_degree, error_variance, savgol_window, savgol_degree. "
      "Returns the report's \"smooth\" section with valid_fraction and model_outputs.");
  m.def("stabilize", &stabilize, py::arg("take"), py::arg("markers") = py::none(), py::arg("keep_stabilized") = true,
        "Removes the head's rigid motion, estimated from head-mounted markers (labels; None: the ones saved "
        "with the take), as `mocap clean --stabilize LABELS --keep-stabilized` does: the markers are left "
        "in head space. Returns the report's \"stabilize\" section (markers, unknown_head_poses, "
        "kept_stabilized) with valid_fraction and model_outputs.");
}

} // namespace mocap::python
