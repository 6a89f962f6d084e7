// mocap.plan_layout: marker layout planning (Wellein et al. 2007) as `mocap pfa` runs it (the
// same core planLayout with the same request), its result as a dict under `mocap pfa --json`'s
// keys (without the rig measure, which mocap pfa --rig adds).

#include "bindings.h"
#include "python_job.h"

#include "mocap/base/error.h"
#include "mocap/layout/layout_planning.h"
#include "mocap/model/marker_edits.h"
#include "mocap/model/take.h"

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace mocap::python {

namespace {

py::dict layoutDict(const LayoutResult& result, const ScoredLayout& layout, bool pfa)
{
  py::dict d;
  d["labels"] = result.labelsOf(layout.markers);
  if (pfa) {
    d["k"] = layout.k;
    d["stability"] = layout.stability;
  }
  d["blendshape_mse"] = layout.blendshapeError;
  d["reconstruction_rmse_mm"] = layout.reconstructionRmse;
  return d;
}

py::object optionalLayout(const LayoutResult& result, const std::optional<ScoredLayout>& layout, bool pfa)
{
  return layout ? py::object(layoutDict(result, *layout, pfa)) : py::object(py::none());
}

py::dict sizeDict(const LayoutResult& result, const LayoutSize& entry)
{
  const SelectionMethod method = result.plan.method;
  py::dict d;
  d["markers"] = entry.markerCount;
  const ScoredLayout* selected = entry.layout(method);
  d["selected"] = selected ? py::object(layoutDict(result, *selected, method == SelectionMethod::Pfa)) : py::none();
  d["pfa"] = optionalLayout(result, entry.pfa, true);
  d["greedy"] = optionalLayout(result, entry.greedy, false);
  py::dict random;
  random["count"] = entry.randomCount;
  random["blendshape_mse"] = entry.randomCount ? py::object(py::float_(entry.randomBlendshapeError)) : py::none();
  random["reconstruction_rmse_mm"] =
      entry.randomCount ? py::object(py::float_(entry.randomReconstructionRmse)) : py::none();
  d["random"] = random;
  return d;
}

py::dict planDict(const LayoutResult& result)
{
  const LayoutPlan& plan = result.plan;
  py::dict d;
  d["method"] = std::string(selectionMethodName(plan.method));
  d["markers"] = result.frames.labels;
  d["stabilize"] = result.stabilizeLabels;
  py::dict frames;
  frames["used"] = result.frames.frames.rows();
  frames["training"] = result.frames.training.size();
  frames["test"] = result.frames.test.size();
  frames["dropped"] = result.frames.droppedFrames;
  frames["stabilized"] = result.frames.stabilized;
  d["frames"] = frames;
  py::dict pca;
  pca["components"] = plan.pcaComponents;
  pca["explained_variance"] = plan.explainedVariance;
  d["pca"] = pca;
  d["motion_rms_mm"] = plan.motionRms;
  py::list sizes;
  for (const LayoutSize& entry : plan.sizes)
    sizes.append(sizeDict(result, entry));
  d["sizes"] = sizes;
  py::dict recommended;
  recommended["markers"] = plan.recommendedSize;
  recommended["rule"] = plan.recommendationRule;
  const ScoredLayout* layout = result.layout(plan.recommendedSize);
  recommended["labels"] = layout ? result.labelsOf(layout->markers) : std::vector<std::string>{};
  recommended["capture_labels"] = layout ? result.captureLabels(layout) : std::vector<std::string>{};
  d["recommended"] = recommended;
  d["cancelled"] = plan.cancelled;
  return d;
}

/// `k`: None, K, or (MIN, MAX), as --k.
void setKRange(PfaOptions& pfa, const py::object& k)
{
  if (k.is_none())
    return;
  const auto range = py::isinstance<py::int_>(k) ? std::pair<long long, long long>(k.cast<long long>(), k.cast<long long>())
                                                 : k.cast<std::pair<long long, long long>>();
  if (range.first < 1 || range.first > range.second)
    throw InvalidArgument("k must be K or (MIN, MAX) with 1 ≤ MIN ≤ MAX, not (" + std::to_string(range.first) + ", " +
                          std::to_string(range.second) + ")");
  pfa.minK = static_cast<Eigen::Index>(range.first);
  pfa.maxK = static_cast<Eigen::Index>(range.second);
}

/// `keyposes`: None or "auto", a str as --keyposes takes it, or frame numbers (ints) of the first take.
std::vector<KeyPose> keyPoses(const py::object& keyposes)
{
  if (keyposes.is_none())
    return {};
  if (py::isinstance<py::str>(keyposes))
    return parseKeyPoses(keyposes.cast<std::string>());
  std::string text;
  for (const long long frame : keyposes.cast<std::vector<long long>>())
    text += (text.empty() ? "" : ",") + std::to_string(frame);
  return parseKeyPoses(text);
}

py::dict planLayoutOf(const py::object& takes, const std::string& method, const py::object& k,
                      std::optional<double> variance, std::optional<int> restarts, std::optional<unsigned long long> seed,
                      std::optional<int> random, const std::optional<std::vector<std::string>>& stabilize,
                      const std::optional<std::vector<std::string>>& markers,
                      const std::optional<std::vector<std::string>>& exclude, const py::object& keyposes,
                      const py::object& pairs, const py::object& progress)
{
  std::vector<Take> copies;
  const py::list list = py::isinstance<Take>(takes) ? py::list(py::make_tuple(takes)) : py::list(takes);
  for (const py::handle take : list) {
    if (!py::isinstance<Take>(take))
      throw py::type_error("plan_layout takes a mocap.Take or a list of them, not a list holding " +
                           std::string(py::str(py::type::of(take).attr("__name__"))));
    copies.push_back(take.cast<const Take&>());
  }
  if (copies.empty())
    throw InvalidArgument("plan_layout needs a take");
  LayoutRequest request;
  const auto parsed = parseSelectionMethod(method);
  if (!parsed)
    throw InvalidArgument("method '" + method + "' is not one of " + selectionMethodNames());
  request.plan.method = *parsed;
  setKRange(request.plan.pfa, k);
  if (variance) {
    if (!(*variance > 0.0 && *variance <= 1.0))
      throw InvalidArgument("variance must be in (0, 1], not " + std::to_string(*variance));
    request.plan.pfa.varianceFraction = *variance;
  }
  if (restarts) {
    if (*restarts < 1)
      throw InvalidArgument("restarts must be 1 or more");
    request.plan.pfa.restarts = *restarts;
  }
  if (seed)
    request.plan.pfa.seed = *seed;
  if (random) {
    if (*random < 0)
      throw InvalidArgument("random must be 0 or more");
    request.plan.randomSubsets = *random;
  }
  request.stabilizeLabels = stabilize.value_or(std::vector<std::string>{});
  request.markerPatterns = markers.value_or(std::vector<std::string>{});
  request.excludePatterns = exclude.value_or(std::vector<std::string>{});
  request.keyPoses = keyPoses(keyposes);
  if (!pairs.is_none())
    request.pairsFile = py::str(py::module_::import("os").attr("fspath")(pairs));
  // planLayout returns a cancelled plan rather than throwing: raised here as any cancelled call is.
  PythonJob job(progress);
  LayoutResult result;
  try {
    const py::gil_scoped_release release;
    result = planLayout(copies, request, job.control());
  } catch (const JobCancelled&) {
    job.raiseCancelled();
  }
  if (result.plan.cancelled)
    job.raiseCancelled();
  return planDict(result);
}

} // namespace

void bindLayout(py::module_& m)
{
  m.def("plan_layout", &planLayoutOf, py::arg("takes"), py::arg("method") = "pfa", py::arg("k") = py::none(),
        py::arg("variance") = py::none(), py::arg("restarts") = py::none(), py::arg("seed") = py::none(),
        py::arg("random") = py::none(), py::arg("stabilize") = py::none(), py::arg("markers") = py::none(),
        py::arg("exclude") = py::none(), py::arg("keyposes") = py::none(), py::arg("pairs") = py::none(),
        py::arg("progress") = py::none(),
        "Plans a reduced marker layout (Wellein et al. 2007) on one take or a list of takes as `mocap pfa` "
        "does, with its options and defaults (None: mocap pfa's default): method ('pfa' or 'greedy'), k "
        "(K or (MIN, MAX)), variance, restarts, seed, random (random layouts per size), stabilize (head "
        "marker labels), markers and exclude (glob patterns), keyposes ('auto', '12,340' or frame numbers), "
        "pairs (a marker-set or pairs file). Returns `mocap pfa --json`'s report as a dict (without the "
        "rig measure): sizes with each method's labels and errors, and recommended {markers, rule, labels, "
        "capture_labels (with the head markers)}. progress(fraction) and Ctrl+C as mocap.solve.");
}

} // namespace mocap::python
