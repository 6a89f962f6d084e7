// Weight curves for other tools: the plain weights CSV and Live Link Face's CSV, through a
// retarget map when one is given, as `mocap solve -o W.csv [--format livelink] [--map M]` writes
// them (app/cli/weight_output.cpp: the same core calls in the same order), and a retarget map
// applied on its own (the Blender add-on's Import Solved Weights).

#include "bindings.h"
#include "finite_weights.h"

#include "mocap/base/error.h"
#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/live_link_face_map.h"
#include "mocap/io/shipped_retarget_maps.h"
#include "mocap/io/weights_csv_writer.h"
#include "mocap/model/retarget_map.h"

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

/// `map` as --map takes it: a shipped map's name or a map file (str or os.PathLike), or None.
std::optional<RetargetMap> retargetMap(const py::object& map)
{
  if (map.is_none())
    return std::nullopt;
  return readRetargetMapByNameOrPath(py::str(py::module_::import("os").attr("fspath")(map)));
}

void writeWeights(const std::filesystem::path& path, const std::vector<std::string>& names,
                  const Eigen::MatrixXd& weights, double rate, long long firstFrame, const py::object& map)
{
  checkFiniteWeights(weights);
  const std::optional<RetargetMap> retarget = retargetMap(map);
  const py::gil_scoped_release release;
  if (!retarget) {
    writeWeightsCsv(path, names, weights, firstFrame, rate);
    return;
  }
  const MappedWeights mapped = applyRetargetMap(*retarget, names, weights);
  writeWeightsCsv(path, mapped.names, mapped.weights, firstFrame, rate);
}

void writeLiveLink(const std::filesystem::path& path, const std::vector<std::string>& names,
                   const Eigen::MatrixXd& weights, double rate, const py::object& map,
                   const std::optional<Eigen::MatrixXd>& headRotation)
{
  checkFiniteWeights(weights);
  if (headRotation && (headRotation->rows() != weights.rows() || (headRotation->cols() != 3 && headRotation->cols() != 9)))
    throw InvalidArgument("head_rotation must be frames × 3 (" + std::to_string(weights.rows()) +
                          " × 3: yaw, pitch, roll in radians; × 9 with each eye's after the head's), not " +
                          std::to_string(headRotation->rows()) +
                          " × " + std::to_string(headRotation->cols()));
  const std::optional<RetargetMap> retarget = retargetMap(map);
  const py::gil_scoped_release release;
  writeLiveLinkFaceCsv(path, liveLinkFaceRecordingOfRig(names, weights, retarget, rate,
                                                        headRotation.value_or(Eigen::MatrixXd())));
}

} // namespace

void bindWeightCurves(py::module_& m)
{
  m.def(
      "retarget_weights",
      [](const std::vector<std::string>& names, const Eigen::MatrixXd& weights, const py::object& map) {
        checkFiniteWeights(weights);
        if (map.is_none())
          throw InvalidArgument("retarget_weights needs a map: a shipped map's name or a map file");
        const RetargetMap retarget = *retargetMap(map);
        MappedWeights mapped;
        {
          const py::gil_scoped_release release;
          mapped = applyRetargetMap(retarget, names, weights);
        }
        return py::make_tuple(mapped.names, mapped.weights);
      },
      py::arg("names"), py::arg("weights"), py::arg("map"),
      "Weight curves (frames × names) through a retarget map (a shipped map's name such as "
      "'arkit_to_ict', or a map file), as --map applies it: returns (channel names, frames × channels). "
      "Raises InvalidArgument naming the map's channel and line for a source the names lack.");
  m.def("write_weights_csv", &writeWeights, py::arg("path"), py::arg("names"), py::arg("weights"), py::arg("rate"),
        py::arg("first_frame") = 0, py::arg("map") = py::none(),
        "Writes weight curves (frames × names) as `mocap solve -o W.csv` does: Frame,Time,<name>,… with "
        "frame i numbered first_frame + i. `map` (a shipped map's name such as 'ict_to_arkit', or a map "
        "file) writes the map's channels instead of the names. Atomic; NaN or inf raise InvalidArgument.");
  m.def("write_live_link_csv", &writeLiveLink, py::arg("path"), py::arg("names"), py::arg("weights"),
        py::arg("rate"), py::arg("map") = py::none(), py::arg("head_rotation") = py::none(),
        "Writes weight curves as Live Link Face's CSV (its 52 ARKit curves, timecodes at 60 fps), as "
        "`mocap solve -o W.csv --format livelink [--map M]` does: through `map` (a shipped map's name or a "
        "map file) or, without one, by identity for ARKit names and the shipped ict_to_arkit map for ICT "
        "names. head_rotation: frames × 3 yaw, pitch, roll in radians, or frames × 9 with the left and right eye's after them (None: zeros). Atomic.");
}

} // namespace mocap::python
