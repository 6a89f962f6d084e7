#include "views/mesh_layer.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkMatrix4x4.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <vector>

namespace mocap::ui {

MeshLayer::MeshLayer(vtkRenderer* renderer) : m_renderer(renderer)
{
  m_points->SetDataTypeToDouble();
  m_data->SetPoints(m_points);
  m_data->SetPolys(m_polygons);
  m_normals->SetInputData(m_data);
  m_normals->SplittingOff();  // keeps one point per vertex, so picked point ids are vertex indices
  m_normals->ConsistencyOff();
  m_mapper->SetInputConnection(m_normals->GetOutputPort());
  m_actor->SetMapper(m_mapper);
  m_actor->SetUserMatrix(m_matrix);
  m_actor->SetVisibility(false);
  m_actor->PickableOn();
  vtkProperty* property = m_actor->GetProperty();
  property->SetSpecular(0.15);
  property->SetEdgeColor(0.35, 0.38, 0.42);
  property->BackfaceCullingOff();
  setColor(QColor(214, 208, 200));
  setOpacity(0.6);
  m_picker->PickFromListOn();
  m_picker->AddPickList(m_actor);
  m_picker->SetTolerance(1e-4);
  m_renderer->AddActor(m_actor);
}

MeshLayer::~MeshLayer()
{
  m_renderer->RemoveActor(m_actor);
}

void MeshLayer::setMesh(const Mesh& mesh)
{
  m_polygons->Reset();
  std::vector<vtkIdType> ids;
  for (const MeshFace& face : mesh.faces) {
    ids.assign(face.vertices.begin(), face.vertices.end());
    m_polygons->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  m_polygons->Modified();
  m_points->SetNumberOfPoints(mesh.vertexCount());
  setVertices(mesh.vertices);
  m_actor->SetVisibility(true);
}

void MeshLayer::clear()
{
  m_polygons->Reset();
  m_points->SetNumberOfPoints(0);
  m_vertices.resize(0, 3);
  m_data->Modified();
  m_actor->SetVisibility(false);
}

void MeshLayer::setVertices(const MeshVertices& vertices)
{
  if (vertices.rows() != m_points->GetNumberOfPoints())
    return;  // another mesh's vertices: keep the drawn ones
  m_vertices = vertices;
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    m_points->SetPoint(v, vertices(v, 0), vertices(v, 1), vertices(v, 2));
  m_points->Modified();
  m_data->Modified();
}

void MeshLayer::setPlacement(const Eigen::Affine3d& meshToScene)
{
  m_placement = meshToScene;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      m_matrix->SetElement(r, c, meshToScene.matrix()(r, c));
  m_matrix->Modified();
  m_actor->Modified();
}

Eigen::Vector3d MeshLayer::scenePosition(Eigen::Index v) const
{
  return m_placement * m_vertices.row(v).transpose();
}

void MeshLayer::setVisible(bool visible)
{
  m_actor->SetVisibility(visible && hasMesh());
}

bool MeshLayer::isVisible() const
{
  return m_actor->GetVisibility() != 0;
}

void MeshLayer::setColor(const QColor& color)
{
  m_actor->GetProperty()->SetColor(static_cast<double>(color.redF()), static_cast<double>(color.greenF()),
                                   static_cast<double>(color.blueF()));
}

void MeshLayer::setOpacity(double opacity)
{
  m_actor->GetProperty()->SetOpacity(opacity);
}

double MeshLayer::opacity() const
{
  return m_actor->GetProperty()->GetOpacity();
}

void MeshLayer::setEdgesVisible(bool visible)
{
  m_actor->GetProperty()->SetEdgeVisibility(visible);
}

bool MeshLayer::edgesVisible() const
{
  return m_actor->GetProperty()->GetEdgeVisibility() != 0;
}

Eigen::Index MeshLayer::vertexAt(const QPoint& pixel) const
{
  if (!isVisible() || m_picker->Pick(pixel.x(), pixel.y(), 0.0, m_renderer) == 0)
    return -1;
  const vtkIdType point = m_picker->GetPointId();
  return point >= 0 && point < m_vertices.rows() ? static_cast<Eigen::Index>(point) : -1;
}

} // namespace mocap::ui
