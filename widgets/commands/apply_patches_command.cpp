#include "commands/apply_patches_command.h"

#include "document/take_document.h"

namespace mocap::ui {

ApplyPatchesCommand::ApplyPatchesCommand(TakeDocument& document, std::vector<SamplePatch> patches,
                                         const QString& text, QUndoCommand* parent)
    : QUndoCommand(text, parent), m_document(document), m_patches(std::move(patches))
{
}

void ApplyPatchesCommand::redo()
{
  m_patches = m_document.applyPatches(std::move(m_patches));
}

void ApplyPatchesCommand::undo()
{
  m_patches = m_document.applyPatches(std::move(m_patches));
}

} // namespace mocap::ui
