#include "commands/replace_weight_curves_command.h"

namespace mocap::ui {

ReplaceWeightCurvesCommand::ReplaceWeightCurvesCommand(BlendshapeSolveModel& model, const QString& text,
                                                       BlendshapeSolveResult curves,
                                                       std::optional<ReadWeightCurves> read)
    : QUndoCommand(text), m_model(model), m_curves(std::move(curves)), m_read(std::move(read)),
      m_generation(model.generation())
{
}

void ReplaceWeightCurvesCommand::swap()
{
  if (m_model.generation() != m_generation) {
    setObsolete(true);  // a new solve or rig replaced the curves this command knew
    return;
  }
  m_model.swapCurves(m_curves, m_read);
}

} // namespace mocap::ui
