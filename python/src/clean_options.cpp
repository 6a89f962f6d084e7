#include "clean_options.h"
#include "python_job.h"

#include "mocap/batch/clean_preset.h"
#include "mocap/batch/clean_report_json.h"
#include "mocap/batch/clean_run.h"

#include "mocap/base/error.h"

namespace py = pybind11;

namespace mocap::python {

CleanOptions parseCleanOptions(const py::dict& preset, const std::string& source)
{
  std::string text;
  try {
    text = py::module_::import("json").attr("dumps")(preset, py::arg("allow_nan") = false).cast<std::string>();
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError))
      throw;
    throw InvalidArgument(source + ": NaN and inf are not option values");
  }
  return parseCleanPreset(text, source);
}

py::dict cleanReportDict(const Take& take, const CleanOptions& options, const CleanReport& report)
{
  return py::module_::import("json").attr("loads")(cleanReportJson("", "", take, options, report));
}

py::dict cleanAndReport(Take& take, const CleanOptions& options, const py::object& progress)
{
  const CleanReport report = runReleased(progress, [&](const JobControl& job) {
    // On a copy, so Ctrl+C leaves the take as it was (never part-cleaned without its history);
    // copied back by assignment, which keeps the buffers NumPy views of the take look into.
    Take cleaned = take;
    CleanReport done = cleanAndRecord(cleaned, options, kCleanTool, job);
    take = cleaned;
    return done;
  });
  return cleanReportDict(take, options, report);
}

} // namespace mocap::python
