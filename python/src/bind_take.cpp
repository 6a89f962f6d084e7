// mocap.Take: a take's samples as NumPy arrays over the take's own storage where the layout
// allows (raw positions, valid flags, states, residuals), copies where Python expects NaN.

#include "bindings.h"

#include "mocap/base/error.h"
#include "mocap/base/length_unit.h"
#include "mocap/model/gaps.h"
#include "mocap/model/take.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>

namespace py = pybind11;

namespace mocap::python {

namespace {

/// A frames × markers array over one of the take's per-sample buffers (column-major: a marker's
/// frames are contiguous), kept alive by the Python Take `owner`.
template <typename T>
py::array sampleView(T* data, const Take& take, py::handle owner)
{
  const auto frames = static_cast<py::ssize_t>(take.frameCount());
  const auto size = static_cast<py::ssize_t>(sizeof(T));
  return py::array_t<T>({frames, static_cast<py::ssize_t>(take.markerCount())}, {size, frames * size}, data, owner);
}

/// frames × markers × 3 over the take's positions: each marker is a block of #frames × 3,
/// column-major, so frame, marker and axis strides are 1, 3·#frames and #frames values.
py::array positionView(Take& take, py::handle owner)
{
  const auto frames = static_cast<py::ssize_t>(take.frameCount());
  const auto size = static_cast<py::ssize_t>(sizeof(double));
  return py::array_t<double>({frames, static_cast<py::ssize_t>(take.markerCount()), py::ssize_t{3}},
                             {size, 3 * frames * size, frames * size}, take.positionData(), owner);
}

/// A copy of the positions with NaN where a sample is not valid.
py::array_t<double> positionsWithGaps(const Take& take)
{
  py::array_t<double> out({take.frameCount(), take.markerCount(), Eigen::Index{3}});
  auto o = out.mutable_unchecked<3>();
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
      const bool valid = take.isValid(f, m);
      const Eigen::Vector3d p = take.position(f, m);
      for (int a = 0; a < 3; ++a)
        o(f, m, a) = valid ? p[a] : std::numeric_limits<double>::quiet_NaN();
    }
  return out;
}

/// Throws ValueError naming the first infinite coordinate: NaN marks a missing sample, but an
/// inf is a broken number, not a gap.
void checkNoInfinity(const py::detail::unchecked_reference<double, 3>& v)
{
  for (py::ssize_t f = 0; f < v.shape(0); ++f)
    for (py::ssize_t m = 0; m < v.shape(1); ++m)
      for (py::ssize_t a = 0; a < 3; ++a)
        if (std::isinf(v(f, m, a)))
          throw py::value_error("positions[" + std::to_string(f) + ", " + std::to_string(m) + ", " +
                                std::to_string(a) + "] is infinite (NaN marks a missing sample)");
}

/// Sets every sample from a float64 array of frames × markers × 3 (any strides); a sample with
/// a NaN coordinate becomes a gap. Raises, changing nothing, for an infinite one. States are
/// left as they are.
void setPositions(Take& take, const py::array& values)
{
  if (!py::isinstance<py::array_t<double>>(values) || values.dtype().kind() != 'f' || values.itemsize() != 8)
    throw py::type_error("positions must be a float64 array, not " + std::string(py::str(values.dtype())));
  if (values.ndim() != 3 || values.shape(0) != take.frameCount() || values.shape(1) != take.markerCount() ||
      values.shape(2) != 3)
    throw py::value_error("positions must have the shape (" + std::to_string(take.frameCount()) + ", " +
                          std::to_string(take.markerCount()) + ", 3)");
  const auto v = values.unchecked<double, 3>();
  checkNoInfinity(v);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
      const Eigen::Vector3d p(v(f, m, 0), v(f, m, 1), v(f, m, 2));
      const bool valid = p.allFinite();
      take.setPosition(f, m, valid ? p : Eigen::Vector3d::Zero());
      take.valid()(f, m) = valid;
    }
}

py::list historyOf(const Take& take)
{
  py::list steps;
  for (const ProcessingStep& step : take.history()) {
    py::dict d;
    d["operation"] = step.operation;
    py::dict parameters;
    for (const auto& [name, value] : step.parameters)
      parameters[py::str(name)] = value;
    d["parameters"] = parameters;
    d["markers"] = step.markers;
    d["first_frame"] = step.firstFrame;
    d["last_frame"] = step.lastFrame;
    d["samples"] = step.samples;
    d["time"] = step.time;
    d["tool"] = step.tool;
    steps.append(d);
  }
  return steps;
}

py::list eventsOf(const Take& take)
{
  py::list events;
  for (const Event& e : take.events()) {
    py::dict d;
    d["label"] = e.label;
    d["context"] = e.context;
    d["description"] = e.description;
    d["subject"] = e.subject;
    d["time"] = e.time;
    events.append(d);
  }
  return events;
}

/// The analog channels as read: rate, identities and scaling, the stored values and the physical
/// ones (AnalogData::physical), each #samples × #channels (copies).
py::dict analogOf(const Take& take)
{
  const AnalogData& analog = take.analog();
  py::dict d;
  d["rate"] = analog.rate;
  d["general_scale"] = analog.generalScale;
  py::list channels;
  for (const AnalogChannel& c : analog.channels) {
    py::dict channel;
    channel["label"] = c.label;
    channel["description"] = c.description;
    channel["unit"] = c.unit;
    channel["scale"] = c.scale;
    channel["offset"] = c.offset;
    channels.append(channel);
  }
  d["channels"] = channels;
  d["stored"] = analog.stored;
  Eigen::MatrixXd physical(analog.sampleCount(), analog.channelCount());
  for (Eigen::Index c = 0; c < analog.channelCount(); ++c)
    physical.col(c) = analog.physical(c);
  d["physical"] = physical;
  return d;
}

void bindGap(py::module_& m)
{
  py::class_<Gap>(m, "Gap", "A run of missing samples of one marker.")
      .def_readonly("marker", &Gap::marker, "the marker's index in Take.labels")
      .def_readonly("first_frame", &Gap::firstFrame, "0-based index of the first missing frame")
      .def_readonly("length", &Gap::length, "missing frames")
      .def_readonly("at_edge", &Gap::atEdge, "touches the first or last frame")
      .def("__repr__", [](const Gap& g) {
        return "Gap(marker=" + std::to_string(g.marker) + ", first_frame=" + std::to_string(g.firstFrame) +
               ", length=" + std::to_string(g.length) + ")";
      });
}

void bindSampleStates(py::module_& m)
{
  m.attr("MEASURED") = static_cast<int>(SampleOrigin::Measured);
  m.attr("FILLED") = static_cast<int>(SampleOrigin::Filled);
  m.attr("EDITED") = static_cast<int>(SampleOrigin::Edited);
  m.attr("SMOOTHED") = static_cast<int>(SampleOperation::Smoothed);
  m.attr("STABILIZED") = static_cast<int>(SampleOperation::Stabilized);
  m.attr("ORIGIN_BITS") = 3;
}

} // namespace

void bindTake(py::module_& m)
{
  bindGap(m);
  bindSampleStates(m);
  py::class_<Take>(m, "Take", py::dynamic_attr(),
                  "A capture: labelled 3-D trajectories at one frame rate, with per-sample states.")
      .def(py::init([](std::vector<std::string> labels, Eigen::Index frames, double rate) {
             if (frames < 0)
               throw InvalidArgument("a take cannot have " + std::to_string(frames) + " frames");
             return Take(std::move(labels), frames, rate);
           }),
           py::arg("labels"), py::arg("frame_count"), py::arg("rate"),
           "An empty take (every sample missing) with these marker labels.")
      .def_property_readonly("labels", &Take::labels, "marker labels, in column order")
      .def_property_readonly("frame_count", &Take::frameCount)
      .def_property_readonly("marker_count", &Take::markerCount)
      .def_property("rate", &Take::frameRate, &Take::setFrameRate, "frames per second")
      .def_property("first_frame", &Take::firstFrame, &Take::setFirstFrame, "the first frame's number in the file")
      .def_property(
          "units", [](const Take& t) { return std::string(unitName(t.units())); },
          [](Take& t, const std::string& unit) {
            const auto parsed = parseLengthUnit(unit);
            if (!parsed)
              throw InvalidArgument("'" + unit + "' is not mm, cm or m");
            t.setUnits(*parsed);
          },
          "length unit of the positions: 'mm', 'cm' or 'm' (setting it relabels, convert_units rescales)")
      .def("convert_units",
           [](Take& t, const std::string& unit) {
             const auto parsed = parseLengthUnit(unit);
             if (!parsed)
               throw InvalidArgument("'" + unit + "' is not mm, cm or m");
             t.convertUnits(*parsed);
           },
           py::arg("unit"), "Rescales the positions to 'mm', 'cm' or 'm'.")
      .def_property("positions", &positionsWithGaps, &setPositions,
                    "frames × markers × 3 float64, a copy with NaN where a sample is missing; assigning an "
                    "array of that shape (any strides) sets every sample (NaN: missing; inf raises ValueError)")
      .def_property_readonly(
          "raw_positions", [](py::object self) { return positionView(self.cast<Take&>(), self); },
          "frames × markers × 3 float64 over the take's own storage (no copy; values in gaps are "
          "whatever the file or a fill left there: read `valid`)")
      .def_property_readonly(
          "valid",
          [](py::object self) {
            Take& t = self.cast<Take&>();
            return sampleView(t.valid().data(), t, self);
          },
          "frames × markers bool over the take's storage: which samples hold a position")
      .def_property_readonly(
          "states",
          [](py::object self) {
            Take& t = self.cast<Take&>();
            return sampleView(t.states().data(), t, self);
          },
          "frames × markers uint8 over the take's storage: origin (state & ORIGIN_BITS: MEASURED, "
          "FILLED, EDITED) and operations (SMOOTHED, STABILIZED bits)")
      .def_property_readonly(
          "residuals",
          [](py::object self) {
            Take& t = self.cast<Take&>();
            return sampleView(t.residuals().data(), t, self);
          },
          "frames × markers float64: the capture system's residual per sample (negative: none)")
      .def("gaps", [](const Take& t) { return findGaps(t); }, "Every run of missing samples, markers in order.")
      .def_property_readonly("history", &historyOf, "the processing steps applied, oldest first")
      .def_property_readonly("events", &eventsOf, "the take's events (label, context, time in s, ...)")
      .def_property_readonly("analog", &analogOf,
                             "the analog channels (force plates, EMG...): {'rate', 'general_scale', 'channels': "
                             "[{label, description, unit, scale, offset}], 'stored': samples × channels as in "
                             "the file, 'physical': (stored − offset) · scale · general_scale}")
      .def("__repr__", [](const Take& t) {
        return "<mocap.Take " + std::to_string(t.markerCount()) + " markers × " + std::to_string(t.frameCount()) +
               " frames at " + std::to_string(t.frameRate()) + " Hz>";
      });
}

} // namespace mocap::python
