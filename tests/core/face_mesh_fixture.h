#pragma once

#include "test_support.h"

#include "mocap/io/obj_io.h"

#include <vector>

namespace mocap::test {

/// The committed MediaPipe canonical face (468 vertices, cm, Y up), read once.
inline const Mesh& mediaPipeFace()
{
  static const Mesh mesh = readObj(dataFile("face_mesh/canonical_face_model.obj"));
  return mesh;
}

/// Vertices first, first + step, … of the face: controls or markers spread over it.
inline std::vector<Eigen::Index> everyNthVertex(Eigen::Index first, Eigen::Index step)
{
  std::vector<Eigen::Index> vertices;
  for (Eigen::Index v = first; v < mediaPipeFace().vertexCount(); v += step)
    vertices.push_back(v);
  return vertices;
}

} // namespace mocap::test
