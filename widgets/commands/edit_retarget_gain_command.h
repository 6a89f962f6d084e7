#pragma once

#include <QString>
#include <QUndoCommand>

namespace mocap::ui {

class RetargetMapModel;

/// Sets one source's gain in the Retarget section's map; undo puts the old gain back (the gains
/// are swapped each time, RetargetMapModel::swapGain). Once another map is loaded it no longer
/// applies and becomes obsolete.
class EditRetargetGainCommand final : public QUndoCommand
{
public:
  EditRetargetGainCommand(RetargetMapModel& model, int channel, int source, double gain, const QString& text);

  void redo() override { swap(); }
  void undo() override { swap(); }

private:
  void swap();

  RetargetMapModel& m_model;
  int m_channel;
  int m_source;
  double m_gain;
  int m_generation;
};

} // namespace mocap::ui
