// mocap.deform: a face mesh driven by a take through a binding, as `mocap deform` drives it (the
// same core FaceRig: RBF or Laplacian, the same options and defaults), the meshes returned as an
// array instead of written.

#include "bindings.h"
#include "mesh_source.h"
#include "python_job.h"

#include "mocap/base/error.h"
#include "mocap/deform/face_rig.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/deform/retarget.h"
#include "mocap/model/take.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace mocap::python {

namespace {

/// `name` parsed by `parse`, or InvalidArgument naming `what` and the choices.
template <typename Parse>
auto parsed(const std::string& name, Parse parse, const char* what, const std::string& choices)
{
  const auto value = parse(name);
  if (!value)
    throw InvalidArgument(std::string(what) + " '" + name + "' is not one of " + choices);
  return *value;
}

struct DeformRequest
{
  std::string method, kernel, weights, scale, up;
  std::optional<double> radius, constraintWeight;
  std::optional<bool> affine, regions;
  std::optional<int> rotations;
  std::optional<long long> neutralFrame;
};

FaceRigOptions rigOptions(const DeformRequest& r)
{
  FaceRigOptions o;  // mocap deform's defaults wherever the request says None
  if (!r.method.empty())
    o.method = parsed(r.method, parseDeformMethod, "method", deformMethodNames());
  if (!r.kernel.empty())
    o.rbf.kernel = parsed(r.kernel, parseRbfKernel, "kernel", "exp, gaussian, biharmonic, thin-plate");
  if (!r.weights.empty())
    o.laplacian.weights = parsed(r.weights, parseLaplacianWeights, "weights", "uniform, cotangent, mean-value");
  if (!r.scale.empty())
    o.scale = parsed(r.scale, parseRetargetScale, "scale", "uniform, per-axis");
  if (!r.up.empty()) {
    if (r.up.size() != 1 || r.up[0] < 'x' || r.up[0] > 'z')
      throw InvalidArgument("up must be 'x', 'y' or 'z', not '" + r.up + "'");
    o.rbf.upAxis = r.up[0] - 'x';
  }
  if (r.radius) {
    if (!(*r.radius > 0.0) || !std::isfinite(*r.radius))
      throw InvalidArgument("radius must be a finite number > 0");
    o.rbf.radius = *r.radius;
  }
  if (r.constraintWeight) {
    if (!(*r.constraintWeight > 0.0) || !std::isfinite(*r.constraintWeight))
      throw InvalidArgument("constraint_weight must be a finite number > 0");
    o.laplacian.constraintWeight = *r.constraintWeight;
  }
  o.rbf.affine = r.affine.value_or(o.rbf.affine);
  o.rbf.regions = r.regions.value_or(o.rbf.regions);
  o.rotations = r.rotations.value_or(o.rotations);
  if (o.rotations > 0 && o.method != DeformMethod::Laplacian)
    throw InvalidArgument("rotations needs method='laplacian'");
  o.neutralFrame = r.neutralFrame;
  return o;
}

/// 0-based [begin, end) of `frames` = (first, last) as the take numbers them; the whole take for None.
std::pair<Eigen::Index, Eigen::Index> frameSpan(const Take& take, const std::optional<std::pair<long long, long long>>& frames)
{
  if (!frames)
    return {0, take.frameCount()};
  const long long first = frames->first - take.firstFrame(), last = frames->second - take.firstFrame();
  if (first < 0 || first > last || last >= take.frameCount())
    throw InvalidArgument("frames must be a range (first, last) within the take's frames " +
                          std::to_string(take.firstFrame()) + "…" +
                          std::to_string(take.firstFrame() + take.frameCount() - 1));
  return {first, last + 1};
}

py::dict deformTake(Take take, const py::object& meshSource, const MeshBinding& binding, const DeformRequest& request,
                    const std::optional<std::vector<std::string>>& stabilize,
                    const std::optional<std::pair<long long, long long>>& frames, const py::object& progress)
{
  const FaceRigOptions options = rigOptions(request);
  const Mesh mesh = meshFrom(meshSource);
  const std::pair<Eigen::Index, Eigen::Index> span = frameSpan(take, frames);
  const Eigen::Index begin = span.first, end = span.second;
  py::array_t<double> out({end - begin, mesh.vertexCount(), Eigen::Index{3}});
  double* values = out.mutable_data();
  Eigen::Index missing = 0, neutral = 0;
  runReleased(progress, [&](const JobControl& control) {
    if (stabilize)
      (void)stabilizeTake(take, *stabilize);
    FaceRig rig(mesh, binding, take, options);
    neutral = rig.neutralFrame();
    MeshVertices deformed;
    for (Eigen::Index f = begin; f < end; ++f) {
      control.checkpoint(static_cast<double>(f - begin) / static_cast<double>(end - begin));
      missing += rig.deform(take, f, deformed) ? 0 : 1;
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
          values + (f - begin) * mesh.vertexCount() * 3, mesh.vertexCount(), 3) = deformed;
    }
    return 0;
  });
  py::dict result;
  result["vertices"] = out;
  result["frames_missing_controls"] = missing;
  result["neutral_frame"] = take.firstFrame() + neutral;
  result["method"] = std::string(deformMethodName(options.method));
  return result;
}

} // namespace

void bindDeform(py::module_& m)
{
  m.def(
      "deform",
      [](const Take& take, const py::object& mesh, const MeshBinding& binding, const std::string& method,
         const std::string& kernel, std::optional<double> radius, std::optional<bool> affine,
         std::optional<bool> regions, const std::string& up, const std::string& weights,
         std::optional<double> constraintWeight, std::optional<int> rotations, const std::string& scale,
         std::optional<long long> neutralFrame, const std::optional<std::vector<std::string>>& stabilize,
         const std::optional<std::pair<long long, long long>>& frames, const py::object& progress) {
        const DeformRequest request{method, kernel, weights, scale, up, radius, constraintWeight,
                                    affine, regions, rotations, neutralFrame};
        return deformTake(take, mesh, binding, request, stabilize, frames, progress);
      },
      py::arg("take"), py::arg("mesh"), py::arg("binding"), py::arg("method") = "", py::arg("kernel") = "",
      py::arg("radius") = py::none(), py::arg("affine") = py::none(), py::arg("regions") = py::none(),
      py::arg("up") = "", py::arg("weights") = "", py::arg("constraint_weight") = py::none(),
      py::arg("rotations") = py::none(), py::arg("scale") = "", py::arg("neutral_frame") = py::none(),
      py::arg("stabilize") = py::none(), py::arg("frames") = py::none(), py::arg("progress") = py::none(),
      "Deforms `mesh` (a mocap.Rig's neutral, or a mesh file) by the take through `binding` as `mocap deform` "
      "does, with its options ('' or None: its defaults): method ('rbf' or 'laplacian'), kernel, radius, "
      "affine, regions, up ('x', 'y', 'z'), weights ('uniform', 'cotangent', 'mean-value'), constraint_weight, "
      "rotations (laplacian), scale ('uniform', 'per-axis'), neutral_frame, stabilize (head marker labels), "
      "frames=(first, last) as the take numbers them. The take is not changed. Returns {'vertices': frames × "
      "vertices × 3 in mesh units, 'frames_missing_controls', 'neutral_frame', 'method'}.");
}

} // namespace mocap::python
