#pragma once
// A face mesh given from Python: a mocap.Rig (its neutral) or a mesh file, as mocap.bind,
// mocap.read_binding and mocap.deform take it.

#include "mocap/model/mesh.h"

#include <pybind11/pybind11.h>

namespace mocap::python {

/// `mesh`'s neutral when it is a mocap.Rig, else the mesh file it names (str or os.PathLike, read
/// as `mocap bind --mesh` reads it, the GIL released). Throws as readMesh. O(file size).
[[nodiscard]] Mesh meshFrom(const pybind11::object& mesh);

} // namespace mocap::python
