#pragma once

#include "mocap/model/processing_step.h"
#include "mocap/model/sample_patch.h"

#include <QUndoCommand>

namespace mocap::ui {

class TakeDocument;

/// Records one processing step in the take's history: redo appends it, undo removes it. Used as
/// the last child of the command that makes the edit, so undo and redo keep the history exactly
/// in step with the samples.
class RecordStepCommand final : public QUndoCommand
{
public:
  RecordStepCommand(TakeDocument& document, ProcessingStep step, QUndoCommand* parent = nullptr);

  void redo() override;
  void undo() override;

private:
  TakeDocument& m_document;
  ProcessingStep m_step;
};

/// A step for `document`'s take stamped with the current time and the studio as tool, for
/// `markers` (indices; all markers when they are all of them) over frames [first, last] (0-based;
/// the whole take when first > last).
[[nodiscard]] ProcessingStep studioStep(const TakeDocument& document, std::string operation,
                                        std::vector<std::pair<std::string, std::string>> parameters,
                                        const std::vector<Eigen::Index>& markers, Eigen::Index first,
                                        Eigen::Index last, std::int64_t samples);

/// One undoable edit that applies `patches` and records it in the take's history as
/// `operation` with `parameters`; the markers, frame range and sample count come from the
/// patches. `parent` (optional) adopts it, as QUndoCommand children do.
[[nodiscard]] QUndoCommand* makeRecordedEdit(TakeDocument& document, std::vector<SamplePatch> patches,
                                             const QString& text, std::string operation,
                                             std::vector<std::pair<std::string, std::string>> parameters,
                                             QUndoCommand* parent = nullptr);

} // namespace mocap::ui
