#pragma once

#include "mocap/model/mesh.h"

#include <Eigen/Geometry>

#include <QColor>
#include <QPoint>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

class vtkActor;
class vtkCellArray;
class vtkCellPicker;
class vtkMatrix4x4;
class vtkPoints;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkPolyDataNormals;
class vtkRenderer;

namespace mocap::ui {

/// A polygon mesh drawn in a VTK renderer (the 3D view's): a smooth-shaded surface whose
/// vertices change every frame, placed in the scene by a similarity (mesh units → the view's
/// coordinates) as the actor's matrix, so the vertices stay in mesh units. Picking returns the
/// vertex under a pixel. Setting vertices costs O(#vertices); the normals are recomputed at the
/// next render, O(#corners).
class MeshLayer
{
public:
  /// Adds the (hidden until setMesh) actor to `renderer`; the destructor removes it (the layer
  /// keeps a reference to the renderer, so the two may be destroyed in either order).
  explicit MeshLayer(vtkRenderer* renderer);
  ~MeshLayer();
  MeshLayer(const MeshLayer&) = delete;
  MeshLayer& operator=(const MeshLayer&) = delete;

  /// Faces and rest vertices of `mesh`; shows the layer.
  void setMesh(const Mesh& mesh);
  void clear();
  [[nodiscard]] bool hasMesh() const { return m_vertices.rows() > 0; }
  /// New vertex positions (#vertices × 3, mesh units); rows must match the mesh.
  void setVertices(const MeshVertices& vertices);
  /// The vertices drawn now, mesh units.
  [[nodiscard]] const MeshVertices& vertices() const { return m_vertices; }
  /// Mesh units → scene coordinates.
  void setPlacement(const Eigen::Affine3d& meshToScene);
  [[nodiscard]] const Eigen::Affine3d& placement() const { return m_placement; }
  /// Where vertex `v` is drawn, in scene coordinates.
  [[nodiscard]] Eigen::Vector3d scenePosition(Eigen::Index v) const;

  void setVisible(bool visible);
  [[nodiscard]] bool isVisible() const;
  void setColor(const QColor& color);
  void setOpacity(double opacity);
  [[nodiscard]] double opacity() const;
  void setEdgesVisible(bool visible);
  [[nodiscard]] bool edgesVisible() const;

  /// The vertex nearest to where the ray through `pixel` (VTK display coordinates: device
  /// pixels, y up) first hits the surface; −1 when it misses. O(#faces).
  [[nodiscard]] Eigen::Index vertexAt(const QPoint& pixel) const;

private:
  vtkSmartPointer<vtkRenderer> m_renderer;  // held: the view may go first when a window closes
  vtkNew<vtkPoints> m_points;
  vtkNew<vtkCellArray> m_polygons;
  vtkNew<vtkPolyData> m_data;
  vtkNew<vtkPolyDataNormals> m_normals;
  vtkNew<vtkPolyDataMapper> m_mapper;
  vtkNew<vtkActor> m_actor;
  vtkNew<vtkMatrix4x4> m_matrix;
  vtkNew<vtkCellPicker> m_picker;
  MeshVertices m_vertices;
  Eigen::Affine3d m_placement = Eigen::Affine3d::Identity();
};

} // namespace mocap::ui
