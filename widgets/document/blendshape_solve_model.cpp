#include "document/blendshape_solve_model.h"

#include "mocap/base/error.h"

#include <algorithm>

namespace mocap::ui {

BlendshapeSolveModel::BlendshapeSolveModel(QObject* parent) : QObject(parent) {}

BlendshapeSolveModel::~BlendshapeSolveModel() = default;

void BlendshapeSolveModel::setRig(std::shared_ptr<const BlendshapeRig> rig, QString path, QString shapeFolder)
{
  m_rig = std::move(rig);
  m_rigPath = std::move(path);
  m_rigShapeFolder = std::move(shapeFolder);
  m_result = {};
  m_read.reset();
  m_selected.clear();
  ++m_generation;
  emit rigChanged();
  emit resultChanged();
  emit selectedShapesChanged();
}

QString BlendshapeSolveModel::shapeName(Eigen::Index shape) const
{
  if (!m_rig || shape < 0 || shape >= m_rig->shapeCount())
    return {};
  return QString::fromStdString(m_rig->shapes[static_cast<std::size_t>(shape)].name);
}

bool BlendshapeSolveModel::setResult(BlendshapeSolveResult result, const BlendshapeSolveOptions& options)
{
  if (!m_rig || result.weights.cols() != m_rig->shapeCount())
    return false;
  m_result = std::move(result);
  m_options = options;
  m_read.reset();
  ++m_generation;
  emit resultChanged();
  return true;
}

void BlendshapeSolveModel::clearResult()
{
  m_result = {};
  m_read.reset();
  ++m_generation;
  emit resultChanged();
}

void BlendshapeSolveModel::setActor(std::shared_ptr<const ActorProfile> actor, QString path)
{
  m_actor = std::move(actor);
  m_actorPath = m_actor ? std::move(path) : QString();
  emit actorChanged();
}

void BlendshapeSolveModel::swapCurves(BlendshapeSolveResult& curves, std::optional<ReadWeightCurves>& read)
{
  std::swap(m_result, curves);
  std::swap(m_read, read);
  emit resultChanged();
}

Eigen::MatrixXd BlendshapeSolveModel::replaceWeights(const std::vector<Eigen::Index>& shapes, Eigen::Index first,
                                                     const Eigen::Ref<const Eigen::MatrixXd>& values)
{
  Eigen::MatrixXd& weights = m_result.weights;
  if (first < 0 || first + values.rows() > weights.rows() || values.cols() != static_cast<Eigen::Index>(shapes.size()))
    throw InvalidArgument("weight edit outside the solved frames");
  for (const Eigen::Index s : shapes)
    if (s < 0 || s >= weights.cols())
      throw InvalidArgument("weight edit of a shape the rig does not have");
  Eigen::MatrixXd before(values.rows(), values.cols());
  for (std::size_t c = 0; c < shapes.size(); ++c) {
    const auto column = static_cast<Eigen::Index>(c);
    before.col(column) = weights.col(shapes[c]).segment(first, values.rows());
    weights.col(shapes[c]).segment(first, values.rows()) = values.col(column).cwiseMax(0.0).cwiseMin(1.0);
  }
  if (values.rows() > 0)
    emit weightsEdited(first, first + values.rows() - 1);
  return before;
}

Eigen::MatrixXd BlendshapeSolveModel::weightBlock(const std::vector<Eigen::Index>& shapes, Eigen::Index first,
                                                  Eigen::Index last) const
{
  const Eigen::Index rows = std::max<Eigen::Index>(last - first + 1, 0);
  Eigen::MatrixXd block(rows, static_cast<Eigen::Index>(shapes.size()));
  for (std::size_t c = 0; c < shapes.size(); ++c)
    block.col(static_cast<Eigen::Index>(c)) = m_result.weights.col(shapes[c]).segment(first, rows);
  return block;
}

void BlendshapeSolveModel::setSelectedShapes(std::vector<Eigen::Index> shapes)
{
  std::sort(shapes.begin(), shapes.end());
  shapes.erase(std::unique(shapes.begin(), shapes.end()), shapes.end());
  if (shapes == m_selected)
    return;
  m_selected = std::move(shapes);
  emit selectedShapesChanged();
}

bool BlendshapeSolveModel::pose(Eigen::Index frame, MeshVertices& out) const
{
  if (!m_rig || frame < 0 || frame >= m_result.weights.rows())
    return false;
  m_rig->evaluate(m_result.weights.row(frame).transpose(), out);
  return true;
}

} // namespace mocap::ui
