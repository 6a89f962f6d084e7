// Core exceptions as Python exceptions with the same messages.

#include "bindings.h"

#include "mocap/base/error.h"
#include "mocap/base/job_control.h"

namespace mocap::python {

void bindErrors(pybind11::module_& m)
{
  // The base first: pybind11 tries the newest translator first, so each subclass maps to its own type.
  auto& error = pybind11::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  auto& format = pybind11::register_exception<FormatError>(m, "FormatError", error.ptr());
  auto& io = pybind11::register_exception<IoError>(m, "IoError", error.ptr());
  auto& invalid = pybind11::register_exception<InvalidArgument>(m, "InvalidArgument", error.ptr());
  auto& cancelled = pybind11::register_exception<JobCancelled>(m, "Cancelled", error.ptr());
  error.attr("__doc__") = "Base of every error the core raises for bad input or failed I/O.";
  format.attr("__doc__") = "A file's content is malformed; the message names the file and where.";
  io.attr("__doc__") = "A file could not be opened, read or written.";
  invalid.attr("__doc__") = "An argument outside its documented range.";
  cancelled.attr("__doc__") = "A long call was stopped (Ctrl+C or a progress callback's request).";
}

} // namespace mocap::python
