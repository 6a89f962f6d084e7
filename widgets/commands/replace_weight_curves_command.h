#pragma once

#include "document/blendshape_solve_model.h"

#include <QString>
#include <QUndoCommand>

#include <optional>

namespace mocap::ui {

/// Replaces all weight curves of the loaded rig at once (a Live Link Face recording opened as
/// curves); undo puts the previous curves back. The curves are swapped each time
/// (BlendshapeSolveModel::swapCurves), so the weight edits on the stack before and after it
/// still apply in order. Once a new solve or rig has replaced the curves it no longer applies
/// and becomes obsolete, as EditWeightsCommand does.
class ReplaceWeightCurvesCommand final : public QUndoCommand
{
public:
  ReplaceWeightCurvesCommand(BlendshapeSolveModel& model, const QString& text, BlendshapeSolveResult curves,
                             std::optional<ReadWeightCurves> read);

  void redo() override { swap(); }
  void undo() override { swap(); }

private:
  void swap();

  BlendshapeSolveModel& m_model;
  BlendshapeSolveResult m_curves;
  std::optional<ReadWeightCurves> m_read;
  int m_generation;
};

} // namespace mocap::ui
