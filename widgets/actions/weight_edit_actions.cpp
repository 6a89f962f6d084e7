#include "actions/weight_edit_actions.h"

#include "commands/edit_weights_command.h"
#include "document/blendshape_solve_model.h"
#include "document/take_document.h"

#include "mocap/cleaning/butterworth_filter.h"
#include "mocap/math/smooth_step.h"

#include <QUndoStack>

#include <algorithm>
#include <cmath>

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
  pushBlended(tr("Scale weights by %1").arg(factor), first, last,
              [&](Eigen::Index from, Eigen::Index to) { return Eigen::MatrixXd(m_model.weightBlock(shapes, from, to) * factor); });
  return {};
}

QString WeightEditActions::zero()
{
  Eigen::Index first = 0, last = 0;
  QString why;
  if (!editedFrames(first, last, why))
    return why;
  const auto shapes = static_cast<Eigen::Index>(m_model.selectedShapes().size());
  pushBlended(tr("Zero weights"), first, last,
              [&](Eigen::Index from, Eigen::Index to) { return Eigen::MatrixXd(Eigen::MatrixXd::Zero(to - from + 1, shapes)); });
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
  pushBlended(tr("Smooth weights (%1 Hz)").arg(cutoffHz), first, last,
              [&](Eigen::Index from, Eigen::Index to) { return Eigen::MatrixXd(smoothed.middleRows(from, to - from + 1)); });
  return {};
}

void WeightEditActions::pushBlended(const QString& text, Eigen::Index first, Eigen::Index last,
                                    const std::function<Eigen::MatrixXd(Eigen::Index, Eigen::Index)>& edit)
{
  // Over a range the edit eases in and out over kBlendSeconds outside it, so the curve keeps no
  // step at the range's edges; over the whole take there is no edge. O(frames · shapes).
  const Eigen::Index frames = m_model.weights().rows();
  const Eigen::Index blend =
      m_document.hasRange() ? std::max<Eigen::Index>(1, std::lround(kBlendSeconds * m_document.take().frameRate())) : 0;
  const Eigen::Index from = std::max<Eigen::Index>(first - blend, 0);
  const Eigen::Index to = std::min<Eigen::Index>(last + blend, frames - 1);
  const std::vector<Eigen::Index>& shapes = m_model.selectedShapes();
  const Eigen::MatrixXd original = m_model.weightBlock(shapes, from, to);
  const Eigen::MatrixXd edited = edit(from, to);
  Eigen::VectorXd weight = Eigen::VectorXd::Ones(to - from + 1);
  for (Eigen::Index f = from; f < first; ++f)  // eases in: 0 before `from`, 1 at `first`
    weight(f - from) = smoothStep(static_cast<double>(f - (first - blend - 1)) / static_cast<double>(blend + 1));
  for (Eigen::Index f = last + 1; f <= to; ++f)  // and out
    weight(f - from) = smoothStep(static_cast<double>(last + blend + 1 - f) / static_cast<double>(blend + 1));
  const Eigen::MatrixXd blended = original + weight.asDiagonal() * (edited - original);
  m_document.undoStack()->push(new EditWeightsCommand(m_model, text, shapes, from, blended));
}

} // namespace mocap::ui
