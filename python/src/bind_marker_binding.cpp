// mocap.bind: a take's markers bound to points of a face mesh, as `mocap bind` binds them (the
// same core calls: stabilizeTake, chooseNeutralFrame, autoBind), on a copy of the take.

#include "bindings.h"
#include "mesh_source.h"

#include "mocap/base/error.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/deform/retarget.h"
#include "mocap/model/take.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace mocap::python {

namespace {

/// The pairs {label: vertex} as marker rows of `labels`, in the dict's order.
std::vector<std::pair<Eigen::Index, Eigen::Index>> pairRows(const py::dict& pairs, const std::vector<std::string>& labels,
                                                            Eigen::Index vertexCount)
{
  std::vector<std::pair<Eigen::Index, Eigen::Index>> rows;
  for (const auto& [key, value] : pairs) {
    const auto label = key.cast<std::string>();
    const auto vertex = value.cast<long long>();
    const auto found = std::find(labels.begin(), labels.end(), label);
    if (found == labels.end())
      throw InvalidArgument("pairs: " + label + " is not one of the markers being bound");
    if (vertex < 0 || vertex >= vertexCount)
      throw InvalidArgument("pairs: vertex " + std::to_string(vertex) + " of " + label + " is not one of the mesh's " +
                            std::to_string(vertexCount));
    rows.emplace_back(found - labels.begin(), static_cast<Eigen::Index>(vertex));
  }
  return rows;
}

std::vector<Eigen::Index> vertexRange(const std::pair<long long, long long>& range, Eigen::Index vertexCount)
{
  if (range.first < 0 || range.first > range.second || range.second >= vertexCount)
    throw InvalidArgument("vertices (" + std::to_string(range.first) + ", " + std::to_string(range.second) +
                          ") must be a range (first, last) within the mesh's vertices 0…" +
                          std::to_string(vertexCount - 1));
  std::vector<Eigen::Index> vertices;
  for (long long v = range.first; v <= range.second; ++v)
    vertices.push_back(static_cast<Eigen::Index>(v));
  return vertices;
}

MeshBinding bindMarkers(Take take, const py::object& meshSource, const std::optional<std::vector<std::string>>& stabilize,
                        std::optional<std::vector<std::string>> labels, std::optional<long long> neutralFrame,
                        const std::optional<py::dict>& pairs, const std::optional<std::pair<long long, long long>>& vertices)
{
  const Mesh mesh = meshFrom(meshSource);
  const std::vector<std::string> reference = stabilize.value_or(std::vector<std::string>{});
  if (!labels) {  // as mocap bind: every marker but the head reference markers
    labels.emplace();
    for (const std::string& label : take.labels())
      if (std::find(reference.begin(), reference.end(), label) == reference.end())
        labels->push_back(label);
  }
  AutoBindOptions options;
  if (pairs)
    options.pairs = pairRows(*pairs, *labels, mesh.vertexCount());
  if (vertices)
    options.vertexSubset = vertexRange(*vertices, mesh.vertexCount());
  const py::gil_scoped_release release;
  (void)stabilizeTake(take, reference);
  const std::vector<Eigen::Index> markers = markerIndices(take, *labels);
  const Eigen::Index neutral = chooseNeutralFrame(take, markers, neutralFrame);
  return autoBind(mesh, *labels, markerPositions(take, neutral, markers), options);
}

} // namespace

void bindMarkerBinding(py::module_& m)
{
  m.def("bind", &bindMarkers, py::arg("take"), py::arg("mesh"), py::arg("stabilize") = py::none(),
        py::arg("markers") = py::none(), py::arg("neutral_frame") = py::none(), py::arg("pairs") = py::none(),
        py::arg("vertices") = py::none(),
        "Binds the take's markers to points of `mesh` (a mocap.Rig's neutral, or a mesh file: .obj, .ply, "
        ".glb) as `mocap bind` does: head motion removed with the `stabilize` reference markers (labels), "
        "the `markers` (labels; default every marker but those) of `neutral_frame` (as the take numbers "
        "frames; default the first where all are seen) aligned to the mesh by ICP, or by `pairs` "
        "({label: vertex}, 3 or more), and bound to the nearest surface points, within `vertices` "
        "(first, last) when given. The take is not changed. Returns a mocap.Binding (Binding.json() is "
        "`mocap bind -o`'s file).");
}

} // namespace mocap::python
