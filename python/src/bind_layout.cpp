// mocap.plan_layout: marker layout planning (Wellein et al. 2007) as `mocap pfa` runs it (the
// same core planLayout with the same request), its result as a dict under `mocap pfa --json`'s
// keys; given a rig and a binding, also the rig measure `mocap pfa --rig` adds (planRigErrors).

#include "bindings.h"
#include "python_job.h"

#include "mocap/base/error.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/evaluation/layout_rig_error.h"
#include "mocap/layout/layout_planning.h"
#include "mocap/model/blendshape_rig.h"
#include "mocap/model/marker_edits.h"
#include "mocap/model/take.h"

#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace mocap::python {

namespace {

/// A rig measure as the JSON gives it: None where not judged.
py::object rigMse(double mse)
{
  return std::isnan(mse) ? py::object(py::none()) : py::object(py::float_(mse));
}

/// The rig measure of `method`'s layout at `markerCount`: NaN without a rig or such a layout.
double rigErrorOf(const PlanRigErrors* rig, Eigen::Index markerCount, SelectionMethod method)
{
  const LayoutSizeRigErrors* entry = rig ? rig->size(markerCount) : nullptr;
  if (!entry)
    return std::nan("");
  const std::optional<RigLayoutError>& error = method == SelectionMethod::Pfa ? entry->pfa : entry->greedy;
  return error ? error->mse : std::nan("");
}

py::dict layoutDict(const LayoutResult& result, const ScoredLayout& layout, bool pfa, double rigError)
{
  py::dict d;
  d["labels"] = result.labelsOf(layout.markers);
  if (pfa) {
    d["k"] = layout.k;
    d["stability"] = layout.stability;
  }
  d["blendshape_mse"] = layout.blendshapeError;
  d["reconstruction_rmse_mm"] = layout.reconstructionRmse;
  d["rig_weight_mse"] = rigMse(rigError);
  return d;
}

py::dict sizeDict(const LayoutResult& result, const LayoutSize& entry, const PlanRigErrors* rig)
{
  const SelectionMethod method = result.plan.method;
  const Eigen::Index size = entry.markerCount;
  py::dict d;
  d["markers"] = size;
  const ScoredLayout* selected = entry.layout(method);
  d["selected"] = selected ? py::object(layoutDict(result, *selected, method == SelectionMethod::Pfa,
                                                   rigErrorOf(rig, size, method)))
                           : py::none();
  for (const SelectionMethod each : {SelectionMethod::Pfa, SelectionMethod::Greedy}) {
    const std::optional<ScoredLayout>& layout = each == SelectionMethod::Pfa ? entry.pfa : entry.greedy;
    d[each == SelectionMethod::Pfa ? "pfa" : "greedy"] =
        layout ? py::object(layoutDict(result, *layout, each == SelectionMethod::Pfa, rigErrorOf(rig, size, each)))
               : py::object(py::none());
  }
  py::dict random;
  random["count"] = entry.randomCount;
  random["blendshape_mse"] = entry.randomCount ? py::object(py::float_(entry.randomBlendshapeError)) : py::none();
  random["reconstruction_rmse_mm"] =
      entry.randomCount ? py::object(py::float_(entry.randomReconstructionRmse)) : py::none();
  const LayoutSizeRigErrors* rigSize = rig ? rig->size(size) : nullptr;
  random["rig_weight_mse"] = rigMse(rigSize ? rigSize->randomMse : std::nan(""));
  if (rigSize)
    random["rig_count"] = rigSize->randomCount;
  d["random"] = random;
  return d;
}

/// `mocap pfa --json`'s "rig" object (without the rig's path: the Rig came from Python), or None.
py::object rigDict(const PlanRigErrors* rig, BlendshapeSolveMethod method)
{
  if (!rig)
    return py::none();
  py::dict d;
  d["method"] = std::string(blendshapeSolveMethodName(method));
  d["bound_markers"] = rig->boundMarkers;
  d["frames"] = rig->frames;
  d["planned_bound_markers"] = rig->planned.boundMarkers;
  d["planned_rig_weight_mse"] = rigMse(rig->planned.mse);
  d["seconds"] = rig->seconds;
  d["cancelled"] = rig->cancelled;
  return std::move(d);
}

py::dict planDict(const LayoutResult& result, const PlanRigErrors* rig, BlendshapeSolveMethod rigMethod)
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
    sizes.append(sizeDict(result, entry, rig));
  d["sizes"] = sizes;
  py::dict recommended;
  recommended["markers"] = plan.recommendedSize;
  recommended["rule"] = plan.recommendationRule;
  const ScoredLayout* layout = result.layout(plan.recommendedSize);
  recommended["labels"] = layout ? result.labelsOf(layout->markers) : std::vector<std::string>{};
  recommended["capture_labels"] = layout ? result.captureLabels(layout) : std::vector<std::string>{};
  d["recommended"] = recommended;
  d["rig"] = rigDict(rig, rigMethod);
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

/// The rig measure asked for (`mocap pfa --rig --binding --rig-method --rig-frames`): the rig and
/// binding, checked to belong together before any planning, so a mistake costs nothing.
struct RigRequest
{
  const BlendshapeRig* rig = nullptr;
  const MeshBinding* binding = nullptr;
  LayoutRigErrorOptions options;
};

RigRequest rigRequest(const py::object& rig, const py::object& binding, const std::optional<std::string>& method,
                      std::optional<long long> frames)
{
  RigRequest request;
  if (rig.is_none()) {
    if (!binding.is_none() || method || frames)
      throw InvalidArgument(std::string(!binding.is_none() ? "binding" : method ? "rig_method" : "rig_frames") +
                            " needs rig= (a mocap.Rig from mocap.load_rig)");
    return request;
  }
  if (binding.is_none())
    throw InvalidArgument("rig= needs binding= (the take's markers bound to the rig's neutral: mocap.read_binding "
                          "or mocap.bind)");
  if (!py::isinstance<BlendshapeRig>(rig) || !py::isinstance<MeshBinding>(binding))
    throw py::type_error("rig= takes a mocap.Rig (mocap.load_rig) and binding= a mocap.Binding (mocap.read_binding)");
  request.rig = &rig.cast<const BlendshapeRig&>();
  request.binding = &binding.cast<const MeshBinding&>();
  if (request.binding->meshVertices != request.rig->neutral.vertexCount())
    throw InvalidArgument("the binding was made for a mesh of " + std::to_string(request.binding->meshVertices) +
                          " vertices, the rig has " + std::to_string(request.rig->neutral.vertexCount()));
  if (method) {
    const auto parsed = parseBlendshapeSolveMethod(*method);
    if (!parsed)
      throw InvalidArgument("rig_method '" + *method + "' is not one of " + blendshapeSolveMethodNames());
    request.options.solve.method = *parsed;
  }
  if (frames) {
    if (*frames < 0)
      throw InvalidArgument("rig_frames must be 0 (every frame) or more");
    request.options.maxFrames = static_cast<Eigen::Index>(*frames);
  }
  return request;
}

py::dict planLayoutOf(const py::object& takes, const std::string& method, const py::object& k,
                      std::optional<double> variance, std::optional<int> restarts, std::optional<unsigned long long> seed,
                      std::optional<int> random, const std::optional<std::vector<std::string>>& stabilize,
                      const std::optional<std::vector<std::string>>& markers,
                      const std::optional<std::vector<std::string>>& exclude, const py::object& keyposes,
                      const py::object& pairs, const py::object& rig, const py::object& binding,
                      const std::optional<std::string>& rigMethod, std::optional<long long> rigFrames,
                      const py::object& progress)
{
  RigRequest rigAsked = rigRequest(rig, binding, rigMethod, rigFrames);
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
  // The rig measure, as mocap pfa --rig runs it: after the plan, with the plan's random count and
  // seed. planLayout and planRigErrors return a cancelled result rather than throwing: raised here
  // as any cancelled call is.
  rigAsked.options.randomSubsets = request.plan.randomSubsets;
  rigAsked.options.seed = request.plan.pfa.seed;
  PythonJob job(progress);
  const JobControl control = job.control();
  LayoutResult result;
  std::optional<PlanRigErrors> rigErrors;
  try {
    const py::gil_scoped_release release;
    result = planLayout(copies, request, rigAsked.rig ? control.part(0.0, 0.5) : control);
    if (rigAsked.rig && !result.plan.cancelled)
      rigErrors = planRigErrors(copies, result, *rigAsked.rig, *rigAsked.binding, rigAsked.options,
                                control.part(0.5, 1.0));
  } catch (const JobCancelled&) {
    job.raiseCancelled();
  }
  if (result.plan.cancelled || (rigErrors && rigErrors->cancelled))
    job.raiseCancelled();
  return planDict(result, rigErrors ? &*rigErrors : nullptr, rigAsked.options.solve.method);
}

} // namespace

void bindLayout(py::module_& m)
{
  m.def("plan_layout", &planLayoutOf, py::arg("takes"), py::arg("method") = "pfa", py::arg("k") = py::none(),
        py::arg("variance") = py::none(), py::arg("restarts") = py::none(), py::arg("seed") = py::none(),
        py::arg("random") = py::none(), py::arg("stabilize") = py::none(), py::arg("markers") = py::none(),
        py::arg("exclude") = py::none(), py::arg("keyposes") = py::none(), py::arg("pairs") = py::none(),
        py::arg("rig") = py::none(), py::arg("binding") = py::none(), py::arg("rig_method") = py::none(),
        py::arg("rig_frames") = py::none(), py::arg("progress") = py::none(),
        "Plans a reduced marker layout (Wellein et al. 2007) on one take or a list of takes as `mocap pfa` "
        "does, with its options and defaults (None: mocap pfa's default): method ('pfa' or 'greedy'), k "
        "(K or (MIN, MAX)), variance, restarts, seed, random (random layouts per size), stabilize (head "
        "marker labels), markers and exclude (glob patterns), keyposes ('auto', '12,340' or frame numbers), "
        "pairs (a marker-set or pairs file). With rig (a mocap.Rig; load_rig(only=...) as --rig-only) and "
        "binding (the markers bound to its neutral), each layout is also judged on the rig as `mocap pfa "
        "--rig` judges it: rig_method (mocap.solve's methods; None: 'bvls'), rig_frames (at most that many "
        "frames per take, 0: all; None: 500). Returns `mocap pfa --json`'s report as a dict: sizes with "
        "each method's labels and errors (rig_weight_mse: None where not judged), the \"rig\" summary "
        "(None without a rig), and recommended {markers, rule, labels, capture_labels (with the head "
        "markers)}. progress(fraction) and Ctrl+C as mocap.solve.");
}

} // namespace mocap::python
