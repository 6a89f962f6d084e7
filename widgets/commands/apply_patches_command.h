#pragma once

#include "mocap/model/sample_patch.h"

#include <QUndoCommand>

#include <vector>

namespace mocap::ui {

class TakeDocument;

/// One undoable edit: a set of sample patches. redo() swaps them into the take and keeps what
/// they replaced; undo() swaps that back, so undo restores the take bit for bit (the data
/// change itself is mocap::swapSamples in core).
class ApplyPatchesCommand final : public QUndoCommand
{
public:
  ApplyPatchesCommand(TakeDocument& document, std::vector<SamplePatch> patches, const QString& text,
                      QUndoCommand* parent = nullptr);

  void redo() override;
  void undo() override;

private:
  TakeDocument& m_document;
  std::vector<SamplePatch> m_patches;  // what the next redo() or undo() puts in
};

} // namespace mocap::ui
