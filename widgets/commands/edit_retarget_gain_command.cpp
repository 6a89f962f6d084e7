#include "commands/edit_retarget_gain_command.h"

#include "document/retarget_map_model.h"

namespace mocap::ui {

EditRetargetGainCommand::EditRetargetGainCommand(RetargetMapModel& model, int channel, int source, double gain,
                                                 const QString& text)
    : QUndoCommand(text), m_model(model), m_channel(channel), m_source(source), m_gain(gain),
      m_generation(model.generation())
{
}

void EditRetargetGainCommand::swap()
{
  if (m_model.generation() != m_generation) {
    setObsolete(true);  // another map was loaded
    return;
  }
  m_gain = m_model.swapGain(m_channel, m_source, m_gain);
}

} // namespace mocap::ui
