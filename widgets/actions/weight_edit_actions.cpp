#include "actions/weight_edit_actions.h"

#include "commands/edit_weights_command.h"
#include "document/blendshape_solve_model.h"
#include "document/take_document.h"

#include "mocap/cleaning/butterworth_filter.h"

#include <QUndoStack>

#include <algorithm>

namespace mocap::ui {

WeightEditActions::WeightEditActions(TakeDocument& document, BlendshapeSolveModel& model, QObject* parent)
    : QObject(parent), m_document(document), m_model(model)
{
}

bool WeightEditActions::editedFrames(Eigen::Index& first, Eigen::Index& last, QString& why) const
{
  if (!m_model.hasResult()) {
    why = tr("Solve the take first.");
    return false;
  }
  if (m_model.selectedShapes().empty()) {
    why = tr("Select the shapes to edit.");
    return false;
  }
  const Eigen::Index frames = m_model.weights().rows();
  first = 0;
  last = frames - 1;
  if (m_document.hasRange()) {
    first = std::clamp<Eigen::Index>(m_document.rangeFirst(), 0, frames - 1);
    last = std::clamp<Eigen::Index>(m_document.rangeLast(), 0, frames - 1);
  }
  return true;
}

QString WeightEditActions::scale(double factor)
{
  Eigen::Index first = 0, last = 0;
  QString why;
  if (!editedFrames(first, last, why))
    return why;
  const std::vector<Eigen::Index>& shapes = m_model.selectedShapes();
  m_document.undoStack()->push(new EditWeightsCommand(m_model, tr("Scale weights by %1").arg(factor), shapes, first,
                                                      m_model.weightBlock(shapes, first, last) * factor));
  return {};
}

QString WeightEditActions::zero()
{
  Eigen::Index first = 0, last = 0;
  QString why;
  if (!editedFrames(first, last, why))
    return why;
  const std::vector<Eigen::Index>& shapes = m_model.selectedShapes();
  m_document.undoStack()->push(
      new EditWeightsCommand(m_model, tr("Zero weights"), shapes, first,
                             Eigen::MatrixXd::Zero(last - first + 1, static_cast<Eigen::Index>(shapes.size()))));
  return {};
}

QString WeightEditActions::smooth(double cutoffHz)
{
  Eigen::Index first = 0, last = 0;
  QString why;
  if (!editedFrames(first, last, why))
    return why;
  const double rate = m_document.take().frameRate();
  if (!(cutoffHz > 0.0) || cutoffHz >= rate / 2.0)
    return tr("The cut-off must lie between 0 and %1 Hz (half the frame rate).").arg(rate / 2.0);
  if (m_model.weights().rows() < kMinButterworthRunLength)
    return tr("The take is too short to smooth.");
  // The whole curves are filtered so the range's values are those of a smooth curve, not of a
  // filter started at the range's edges.
  const std::vector<Eigen::Index>& shapes = m_model.selectedShapes();
  const Eigen::MatrixXd all = m_model.weightBlock(shapes, 0, m_model.weights().rows() - 1);
  const Eigen::MatrixXd smoothed = butterworthFilter(all, rate, cutoffHz);
  m_document.undoStack()->push(new EditWeightsCommand(m_model, tr("Smooth weights (%1 Hz)").arg(cutoffHz), shapes,
                                                      first, smoothed.middleRows(first, last - first + 1)));
  return {};
}

} // namespace mocap::ui
