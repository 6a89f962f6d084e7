#include "commands/acknowledge_data_loss_command.h"

#include "commands/record_step_command.h"
#include "document/take_document.h"

#include "mocap/model/data_loss_record.h"

#include <QCoreApplication>
#include <QUndoCommand>

namespace mocap::ui {

QUndoCommand* makeAcknowledgeDataLoss(TakeDocument& document)
{
  QUndoCommand* command = nullptr;
  for (const DataLossRecord& record : dataLossRecords(document.take())) {
    if (record.acknowledged)
      continue;
    if (!command)
      command = new QUndoCommand(QCoreApplication::translate("AcknowledgeDataLoss", "Acknowledge data loss"));
    new RecordStepCommand(document, acknowledgementOf(record, "mocap-studio", currentUtcTime()), command);
  }
  return command;
}

} // namespace mocap::ui
