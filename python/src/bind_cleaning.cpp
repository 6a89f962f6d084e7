// mocap.clean: the `mocap clean` pipeline on a Take in place, its options given as a cleaning
// preset (a file or a dict) and/or keyword arguments of the same shape, so the names, defaults
// and checks are the preset reader's (batch/clean_preset.h), not a second copy of them.

#include "bindings.h"
#include "clean_options.h"

#include "mocap/base/file_io.h"
#include "mocap/model/take.h"

#include <pybind11/stl.h>

#include <string>

namespace py = pybind11;

namespace mocap::python {

namespace {

/// `preset` (a path, a dict or None) with `options` laid over it, each step either a dict of its
/// options or "off".
py::dict mergedPreset(const py::object& preset, const py::kwargs& options)
{
  py::dict merged;
  if (py::isinstance<py::dict>(preset)) {
    merged = py::dict(preset);
  } else if (!preset.is_none()) {
    const std::string path = py::str(py::module_::import("os").attr("fspath")(preset));
    merged = py::module_::import("json").attr("loads")(readFileBytes(path));  // IoError as the CLI gives it
  }
  for (const auto& [key, value] : options) {
    if (py::isinstance<py::str>(value) && value.cast<std::string>() == "off")
      merged[key] = py::dict(py::arg("method") = "off");
    else
      merged[key] = value;
  }
  return merged;
}

} // namespace

void bindCleaning(py::module_& m)
{
  m.def(
      "clean",
      [](Take& take, const py::object& preset, const py::object& progress, const py::kwargs& options) {
        const std::string source = preset.is_none() || py::isinstance<py::dict>(preset)
                                       ? std::string("mocap.clean options")
                                       : py::str(preset).cast<std::string>();
        return cleanAndReport(take, parseCleanOptions(mergedPreset(preset, options), source), progress);
      },
      py::arg("take"), py::arg("preset") = py::none(), py::arg("progress") = py::none(),
      "Cleans the take in place as `mocap clean` does (stabilize → spikes → fill → smooth) and "
      "returns the report `mocap clean --report` writes, as a dict. Options are a cleaning preset "
      "(a JSON file's path or a dict, `mocap batch --preset`'s format) and/or keyword arguments of "
      "the same shape, which win: spikes={\"method\": \"robust\", \"factor\": 1.5}, "
      "fill={\"max_gap_seconds\": 1.0}, smooth=\"off\", stabilize={\"markers\": [\"head1\", …]}. "
      "Left out: `mocap clean`'s defaults. progress(fraction) is called as the work goes on (False "
      "from it, or Ctrl+C, stops the clean at its next checkpoint and leaves the take as it was: "
      "KeyboardInterrupt or mocap.Cancelled). Raises InvalidArgument naming the key for an unknown "
      "key or a value out of range.");
}

} // namespace mocap::python
