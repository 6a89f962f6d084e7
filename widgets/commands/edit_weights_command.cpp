#include "commands/edit_weights_command.h"

#include "document/blendshape_solve_model.h"

namespace mocap::ui {

EditWeightsCommand::EditWeightsCommand(BlendshapeSolveModel& model, const QString& text,
                                       std::vector<Eigen::Index> shapes, Eigen::Index first, Eigen::MatrixXd values)
    : QUndoCommand(text), m_model(model), m_shapes(std::move(shapes)), m_first(first), m_values(std::move(values)),
      m_generation(model.generation())
{
}

void EditWeightsCommand::swap()
{
  if (m_model.generation() != m_generation) {
    setObsolete(true);
    return;
  }
  m_values = m_model.replaceWeights(m_shapes, m_first, m_values);
}

} // namespace mocap::ui
