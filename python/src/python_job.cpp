#include "python_job.h"

#include <utility>

namespace py = pybind11;

namespace mocap::python {

PythonJob::PythonJob(py::object progress) : m_progress(std::move(progress)) {}

JobControl PythonJob::control() const
{
  // The control may outlive a report in flight on a worker thread only as long as the call,
  // which the PythonJob outlives: capturing `this` is safe.
  auto* self = const_cast<PythonJob*>(this);
  return JobControl([self](double fraction) { self->report(fraction); }, m_cancel);
}

void PythonJob::report(double fraction)
{
  if (m_cancel->load())
    return;
  const py::gil_scoped_acquire acquire;
  try {
    if (PyErr_CheckSignals() != 0)
      throw py::error_already_set();
    if (!m_progress.is_none()) {
      const py::object answer = m_progress(fraction);
      if (!answer.is_none() && !answer.cast<bool>()) {
        m_cancel->store(true);
        return;
      }
    }
  } catch (py::error_already_set& e) {
    m_error = std::make_shared<py::error_already_set>(std::move(e));
    m_cancel->store(true);
  }
}

void PythonJob::raiseCancelled()
{
  if (m_error) {
    m_error->restore();
    throw py::error_already_set();
  }
  throw JobCancelled();
}

} // namespace mocap::python
