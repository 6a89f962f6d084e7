#pragma once

class QUndoCommand;

namespace mocap::ui {

class TakeDocument;

/// One undoable edit by which a person acknowledges every data-loss finding of the document's
/// take not acknowledged yet: a history step each (kDataLossAcknowledgedOperation, data_loss_record.h),
/// saved with the take, so later reads of a saved copy list the finding as acknowledged instead of
/// raising it. Null when there is nothing to acknowledge.
[[nodiscard]] QUndoCommand* makeAcknowledgeDataLoss(TakeDocument& document);

} // namespace mocap::ui
