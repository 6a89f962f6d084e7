#include "mesh_source.h"

#include "mocap/io/mesh_io.h"
#include "mocap/model/blendshape_rig.h"

#include <string>

namespace py = pybind11;

namespace mocap::python {

Mesh meshFrom(const py::object& mesh)
{
  if (py::isinstance<BlendshapeRig>(mesh))
    return mesh.cast<const BlendshapeRig&>().neutral;
  const std::string path = py::str(py::module_::import("os").attr("fspath")(mesh));
  const py::gil_scoped_release release;
  return readMesh(path);
}

} // namespace mocap::python
