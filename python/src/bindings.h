#pragma once
// The parts of the `mocap` Python module, one per concept; mocap_module.cpp calls each once.

#include <pybind11/pybind11.h>

namespace mocap::python {

/// mocap.Error and its subclasses FormatError, IoError, InvalidArgument and Cancelled, raised
/// with the core's own messages.
void bindErrors(pybind11::module_& m);
/// mocap.Take: labels, rate, units, positions as NumPy arrays, sample states, gaps, history.
void bindTake(pybind11::module_& m);
/// mocap.read and Take.write: every format the core reads and writes.
void bindTakeFiles(pybind11::module_& m);
/// mocap.clean: `mocap clean`'s pipeline with a preset's options.
void bindCleaning(pybind11::module_& m);
/// mocap.detect_spikes, fill_gaps, smooth, stabilize: `mocap clean` with one step on.
void bindCleaningSteps(pybind11::module_& m);
/// mocap.Rig, mocap.load_rig, mocap.Binding, mocap.read_binding and mocap.solve.
void bindSolve(pybind11::module_& m);
/// mocap.bind: markers bound to a mesh as `mocap bind` binds them.
void bindMarkerBinding(pybind11::module_& m);
/// mocap.deform: a face mesh driven by a take as `mocap deform` drives it (RBF or Laplacian).
void bindDeform(pybind11::module_& m);
/// mocap.plan_layout: marker layout planning as `mocap pfa` runs it.
void bindLayout(pybind11::module_& m);
/// mocap.write_rig_glb, write_rig_fbx, write_markers_fbx, write_pc2.
void bindWriters(pybind11::module_& m);
/// mocap.write_weights_csv, write_live_link_csv, retarget_weights.
void bindWeightCurves(pybind11::module_& m);
/// mocap.write_review_video: `mocap review`'s video, rendered by the command line (no Qt here).
void bindReviewVideo(pybind11::module_& m);

} // namespace mocap::python
