// Writers of solved animation for animation tools: the rig with its weights as glTF or FBX, the
// markers as FBX, and the posed mesh as an OBJ + PC2 point cache (Blender's Mesh Cache).

#include "bindings.h"
#include "finite_weights.h"

#include "mocap/base/error.h"
#include "mocap/io/fbx_writer.h"
#include "mocap/io/gltf_writer.h"
#include "mocap/io/mesh_sequence_writer.h"
#include "mocap/math/key_reduction.h"
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

FbxUpAxis upAxis(const std::string& up)
{
  const auto axis = parseFbxUpAxis(up);
  if (!axis)
    throw InvalidArgument("up must be 'y' or 'z', not '" + up + "'");
  return *axis;
}

/// The keys kept, as `mocap solve --json` reports them, or None without a tolerance.
py::object keyReport(std::optional<double> tolerance, const KeyCount& count)
{
  if (!tolerance)
    return py::none();
  py::dict d;
  d["tolerance"] = *tolerance;
  d["keys_before"] = count.before;
  d["keys_after"] = count.after;
  d["max_error"] = count.maxError;
  return std::move(d);
}

} // namespace

void bindWriters(py::module_& m)
{
  m.def(
      "write_rig_glb",
      [](const std::filesystem::path& path, const BlendshapeRig& rig, const Eigen::MatrixXd& weights, double rate,
         std::optional<double> reduce) {
        KeyCount count;
        {
          const py::gil_scoped_release release;
          std::vector<Eigen::Index> keys;  // empty: every frame
          if (reduce && weights.rows() > 0) {
            const KeyReduction shared = reduceFrameKeys(weights, *reduce);
            count.add(weights.rows(), static_cast<Eigen::Index>(shared.keys.size()), shared.maxError);
            keys = shared.keys;
          }
          writeRigGlb(path, rig, weights, rate, keys);
        }
        return keyReport(reduce, count);
      },
      py::arg("path"), py::arg("rig"), py::arg("weights"), py::arg("rate"), py::arg("reduce") = py::none(),
      "Writes the rig as glTF (.glb) with one morph target per shape and `weights` (frames × shapes) as "
      "its animation, as `mocap solve -o R.glb` does; `reduce` keeps the fewest key frames, shared by "
      "every shape, within that many weight units, and the key frames kept are returned (else None). Atomic.");
  m.def(
      "write_rig_fbx",
      [](const std::filesystem::path& path, const BlendshapeRig& rig, const Eigen::MatrixXd& weights, double rate,
         const std::string& up, const std::string& units, std::optional<double> reduce) {
        FbxRigOptions options;
        options.up = upAxis(up);
        const auto unit = parseLengthUnit(units);
        if (!unit || *unit == LengthUnit::Metre)
          throw InvalidArgument("units must be 'cm' or 'mm', not '" + units + "'");
        options.unit = *unit;
        KeyCount count;
        if (reduce)
          options.keys = {reduce, &count};
        {
          const py::gil_scoped_release release;
          writeRigFbx(path, rig, weights, rate, options);
        }
        return keyReport(reduce, count);
      },
      py::arg("path"), py::arg("rig"), py::arg("weights"), py::arg("rate"), py::arg("up") = "y",
      py::arg("units") = "cm", py::arg("reduce") = py::none(),
      "Writes the rig as binary FBX (a skinned mesh with one blend shape channel per shape and "
      "DeformPercent curves), as `mocap solve -o R.fbx` does; `reduce` keys each curve within that "
      "many weight units and the keys kept are returned (else None). Atomic.");
  m.def(
      "write_markers_fbx",
      [](const std::filesystem::path& path, const Take& take, const std::string& up, std::optional<double> reduceMm) {
        KeyCount count;
        FbxCurveKeys keys;
        if (reduceMm)
          keys = {*reduceMm / millimetresPer(take.units()), &count};
        {
          const py::gil_scoped_release release;
          writeMarkersFbx(path, take, upAxis(up), keys);
        }
        if (reduceMm)
          count.maxError *= millimetresPer(take.units());
        return keyReport(reduceMm, count);
      },
      py::arg("path"), py::arg("take"), py::arg("up") = "z", py::arg("reduce") = py::none(),
      "Writes the markers as animated FBX nulls, as `mocap convert TAKE OUT.fbx` does; `reduce` (mm) "
      "keeps each marker within that distance of every frame and returns the keys kept.");
  m.def(
      "write_pc2",
      [](const std::filesystem::path& path, const BlendshapeRig& rig, const Eigen::MatrixXd& weights,
         double firstFrame) {
        checkFiniteWeights(weights);  // the glTF and FBX writers check theirs; a point cache would keep NaN
        if (weights.cols() != rig.shapeCount())
          throw InvalidArgument("weights has " + std::to_string(weights.cols()) + " columns for the rig's " +
                                std::to_string(rig.shapeCount()) + " shapes");
        const py::gil_scoped_release release;
        MeshSequenceWriter sink(path, rig.neutral, MeshSequenceFormat::ObjPlusPc2, path.stem().string(),
                                static_cast<float>(firstFrame));
        MeshVertices posed;
        for (Eigen::Index f = 0; f < weights.rows(); ++f) {
          rig.evaluate(weights.row(f).transpose(), posed);
          sink.add(posed);
        }
        sink.finish();
      },
      py::arg("path"), py::arg("rig"), py::arg("weights"), py::arg("first_frame") = 0.0,
      "Writes the rig posed by each frame's weights as a .pc2 point cache with the rest mesh as .obj "
      "beside it (Blender's Mesh Cache modifier), as `mocap solve -o M.pc2` does.");
}

} // namespace mocap::python
