#pragma once

#include <QString>
#include <QUndoCommand>

#include <Eigen/Core>

#include <vector>

namespace mocap::ui {

class BlendshapeSolveModel;

/// Replaces a block of solved blendshape weights (some shapes over a frame range: a scale, a
/// zero, a smoothing); undo puts the old values back (the block is swapped each time,
/// BlendshapeSolveModel::replaceWeights). It lives on the document's undo stack with every other
/// edit; once a new solve or rig has replaced the weights it no longer applies and becomes
/// obsolete, so the stack drops it.
class EditWeightsCommand final : public QUndoCommand
{
public:
  EditWeightsCommand(BlendshapeSolveModel& model, const QString& text, std::vector<Eigen::Index> shapes,
                     Eigen::Index first, Eigen::MatrixXd values);

  void redo() override { swap(); }
  void undo() override { swap(); }

private:
  void swap();

  BlendshapeSolveModel& m_model;
  std::vector<Eigen::Index> m_shapes;
  Eigen::Index m_first;
  Eigen::MatrixXd m_values;
  int m_generation;
};

} // namespace mocap::ui
