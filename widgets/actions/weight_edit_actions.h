#pragma once

#include <Eigen/Core>

#include <QObject>
#include <QString>

#include <functional>

namespace mocap::ui {

class BlendshapeSolveModel;
class TakeDocument;

/// The Blendshape solve panel's edits of solved weights, each one undoable EditWeightsCommand on
/// the document's stack: over the selected frame range (TakeDocument::range, or the whole take
/// without one), the selected shapes' curves are scaled, zeroed or smoothed (a zero-lag
/// Butterworth low-pass of the whole curve, kept inside the range). Over a range, the edit eases in
/// and out over kBlendSeconds either side of it (a smooth step from the curve to the edit), so it
/// leaves no step at the range's edges. Results are clamped to [0, 1]. An edit that cannot apply
/// says why in the returned message and pushes nothing.
class WeightEditActions final : public QObject
{
  Q_OBJECT

public:
  /// How long an edit of a range takes to ease in before it and out after it.
  static constexpr double kBlendSeconds = 0.1;

  WeightEditActions(TakeDocument& document, BlendshapeSolveModel& model, QObject* parent = nullptr);

  /// Each returns "" or why nothing was done.
  QString scale(double factor);
  QString zero();
  QString smooth(double cutoffHz);

private:
  /// The frames an edit covers, [first, last]; false (with `why`) when there is nothing to edit.
  bool editedFrames(Eigen::Index& first, Eigen::Index& last, QString& why) const;
  /// Pushes the edit of [first, last] blended into the curves around it: `edit(from, to)` gives the
  /// edited selected shapes over [from, to], a span that holds the range and its blend frames.
  void pushBlended(const QString& text, Eigen::Index first, Eigen::Index last,
                   const std::function<Eigen::MatrixXd(Eigen::Index, Eigen::Index)>& edit);

  TakeDocument& m_document;
  BlendshapeSolveModel& m_model;
};

} // namespace mocap::ui
