#pragma once

#include <Eigen/Core>

#include <QObject>
#include <QString>

namespace mocap::ui {

class BlendshapeSolveModel;
class TakeDocument;

/// The Blendshape solve panel's edits of solved weights, each one undoable EditWeightsCommand on
/// the document's stack: over the selected frame range (TakeDocument::range, or the whole take
/// without one), the selected shapes' curves are scaled, zeroed or smoothed (a zero-lag
/// Butterworth low-pass of the whole curve, kept inside the range). Results are clamped to
/// [0, 1]. An edit that cannot apply says why in the returned message and pushes nothing.
class WeightEditActions final : public QObject
{
  Q_OBJECT

public:
  WeightEditActions(TakeDocument& document, BlendshapeSolveModel& model, QObject* parent = nullptr);

  /// Each returns "" or why nothing was done.
  QString scale(double factor);
  QString zero();
  QString smooth(double cutoffHz);

private:
  /// The frames an edit covers, [first, last]; false (with `why`) when there is nothing to edit.
  bool editedFrames(Eigen::Index& first, Eigen::Index& last, QString& why) const;

  TakeDocument& m_document;
  BlendshapeSolveModel& m_model;
};

} // namespace mocap::ui
