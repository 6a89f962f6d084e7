#pragma once

#include "mocap/model/take.h"

#include <QUndoCommand>

#include <optional>

namespace mocap::ui {

class TakeDocument;

/// Replaces the whole take with one computed from it (tracking and labelling, swap repair):
/// redo and undo exchange the two takes, so undo restores the take bit for bit. Costs one copy
/// of the take in the history. The replacement inherits the take's processing history, plus
/// `step` when given, so the history always says how the current take was made.
class ReplaceTakeCommand final : public QUndoCommand
{
public:
  ReplaceTakeCommand(TakeDocument& document, Take replacement, const QString& text,
                     std::optional<ProcessingStep> step = std::nullopt);

  void redo() override { swap(); }
  void undo() override { swap(); }

private:
  void swap();

  TakeDocument& m_document;
  Take m_other;  // the take that the next redo() or undo() puts in
};

} // namespace mocap::ui
