// Rigs, bindings and the blendshape solve: mocap.load_rig, mocap.read_binding, mocap.solve.

#include "bindings.h"
#include "finite_weights.h"
#include "mesh_source.h"
#include "python_job.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/deform/blendshape_solver.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/io/rig_io.h"
#include "mocap/model/blendshape_rig.h"
#include "mocap/model/take.h"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace mocap::python {

namespace {

void bindRig(py::module_& m)
{
  py::class_<BlendshapeRig>(m, "Rig", "A neutral mesh with named blendshapes (0 ≤ weight ≤ 1).")
      .def_property_readonly("names", &BlendshapeRig::shapeNames, "the shapes' names, in weight-column order")
      .def_property_readonly("shape_count", &BlendshapeRig::shapeCount)
      .def_property_readonly("vertex_count", [](const BlendshapeRig& r) { return r.neutral.vertexCount(); })
      .def_property_readonly(
          "neutral", [](const BlendshapeRig& r) -> MeshVertices { return r.neutral.vertices; },
          "the neutral's vertices, #vertices × 3 (a copy)")
      .def(
          "evaluate",
          [](const BlendshapeRig& r, const Eigen::VectorXd& weights) {
            checkFiniteWeights(weights.transpose());
            MeshVertices posed;
            r.evaluate(weights, posed);
            return posed;
          },
          py::arg("weights"), "The mesh posed by one weight per shape: neutral + Σ wₛ·Δₛ.")
      .def("__repr__", [](const BlendshapeRig& r) {
        return "<mocap.Rig " + std::to_string(r.shapeCount()) + " shapes on " +
               std::to_string(r.neutral.vertexCount()) + " vertices>";
      });
  m.def(
      "load_rig",
      [](const std::filesystem::path& mesh, std::optional<std::filesystem::path> shapes,
         std::vector<std::string> only) {
        if (!isGltfPath(mesh) && !shapes)
          throw InvalidArgument("an OBJ/PLY neutral needs shapes= (the folder of shape meshes)");
        const py::gil_scoped_release release;
        return readRig(mesh, shapes.value_or(std::filesystem::path()), only);
      },
      py::arg("mesh"), py::arg("shapes") = py::none(), py::arg("only") = std::vector<std::string>{},
      "Reads a rig as `mocap solve --mesh` does: a glTF file with morph targets, or an OBJ/PLY neutral "
      "with a folder of shapes; `only` keeps those shapes, in that order.");
}

void bindBinding(py::module_& m)
{
  py::class_<MeshBinding>(m, "Binding", "Which mesh point each marker drives, and the take-to-mesh alignment.")
      .def_property_readonly("labels",
                             [](const MeshBinding& b) {
                               std::vector<std::string> labels;
                               for (const MarkerBinding& marker : b.markers)
                                 labels.push_back(marker.label);
                               return labels;
                             })
      .def_property_readonly("residuals",
                             [](const MeshBinding& b) {
                               std::vector<double> residuals;
                               for (const MarkerBinding& marker : b.markers)
                                 residuals.push_back(marker.residual);
                               return residuals;
                             },
                             "per marker, the distance from its aligned neutral position to its mesh point (mm)")
      .def_readonly("mesh_vertices", &MeshBinding::meshVertices)
      .def("json", &bindingJson, "The binding as `mocap bind -o` writes it.")
      .def(
          "write", [](const MeshBinding& b, const std::filesystem::path& path) { writeFileAtomically(path, bindingJson(b)); },
          py::arg("path"), "Writes json() to `path` atomically.");
  m.def(
      "read_binding",
      [](const std::filesystem::path& path, const py::object& mesh) {
        return readBinding(path, meshFrom(mesh).vertexCount());
      },
      py::arg("path"), py::arg("mesh"),
      "Reads a binding (`mocap bind`'s JSON) made for `mesh` (a mocap.Rig, or the mesh file it was bound "
      "to); raises when it was made for another vertex count.");
}

BlendshapeSolveOptions solveOptions(const std::string& method, std::optional<double> lambda, double smoothness,
                                    double sparsity, std::optional<long long> neutralFrame)
{
  BlendshapeSolveOptions options;
  const auto parsed = parseBlendshapeSolveMethod(method);
  if (!parsed)
    throw InvalidArgument("method '" + method + "' is not one of " + blendshapeSolveMethodNames());
  options.method = *parsed;
  options.lambda = lambda;
  options.smoothness = smoothness;
  options.sparsity = sparsity;
  options.neutralFrame = neutralFrame;
  return options;
}

} // namespace

void bindSolve(py::module_& m)
{
  bindRig(m);
  bindBinding(m);
  m.def(
      "solve",
      [](const Take& take, const BlendshapeRig& rig, const MeshBinding& binding, const std::string& method,
         std::optional<double> lambda, double smoothness, double sparsity, std::optional<long long> neutralFrame,
         const py::object& progress) {
        const BlendshapeSolveOptions options = solveOptions(method, lambda, smoothness, sparsity, neutralFrame);
        const BlendshapeSolveResult result = runReleased(progress, [&](const JobControl& control) {
          const BlendshapeSolver solver(rig, binding, take, options);
          return solver.solve(take, {}, control);
        });
        py::dict out;
        out["weights"] = result.weights;
        out["names"] = rig.shapeNames();
        out["residual"] = result.residual;
        out["held"] = result.held;
        out["lambda"] = result.lambda;
        return out;
      },
      py::arg("take"), py::arg("rig"), py::arg("binding"), py::arg("method") = "temporal",
      py::arg("lambda_") = py::none(), py::arg("smoothness") = 1.0, py::arg("sparsity") = 0.0,
      py::arg("neutral_frame") = py::none(), py::arg("progress") = py::none(),
      "Solves the take to the rig's weights as `mocap solve` does (same methods and defaults). "
      "Returns {'weights': frames × shapes, 'names', 'residual' (per frame, take units), 'held' "
      "(frames with too few markers), 'lambda'}. `progress(fraction)` is called about every 50 ms; "
      "returning False, or Ctrl+C, stops the solve (mocap.Cancelled, or KeyboardInterrupt).");
}

} // namespace mocap::python
