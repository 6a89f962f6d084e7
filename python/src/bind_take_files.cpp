// mocap.read and Take.write: every take format the core reads and writes, the GIL released
// while the file is parsed or written.

#include "bindings.h"

#include "mocap/io/take_io.h"
#include "mocap/model/take.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>
#include <vector>

namespace py = pybind11;

namespace mocap::python {

void bindTakeFiles(py::module_& m)
{
  m.def(
      "read",
      [](const std::filesystem::path& path) {
        std::vector<std::string> warnings, dataLoss;
        Take take;
        {
          const py::gil_scoped_release release;
          take = readTake(path, &warnings, &dataLoss);
        }
        py::object result = py::cast(std::move(take));
        result.attr("warnings") = warnings;
        result.attr("data_loss") = dataLoss;
        return result;
      },
      py::arg("path"),
      "Reads a take (.c3d, .trc; the format from the extension). The take's `warnings` lists the "
      "file's tolerated quirks and `data_loss` those that mean data is missing (a truncated file) or "
      "wrong (wrapped coordinates), with those a saved copy's history carried and nobody acknowledged. Raises IoError, FormatError, or InvalidArgument for a format it cannot read.");
  py::class_<Take> take = py::reinterpret_borrow<py::class_<Take>>(m.attr("Take"));
  take.def(
      "write",
      [](const Take& t, const std::filesystem::path& path) {
        const py::gil_scoped_release release;
        writeTake(t, path);
      },
      py::arg("path"),
      "Writes the take atomically in the format its extension names (.c3d, .trc, .csv, .bvh, .fbx); "
      "TRC and CSV get a provenance sidecar when the take has sample states or history. On failure "
      "the previous file is kept.");
}

} // namespace mocap::python
