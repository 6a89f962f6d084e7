#include "commands/record_step_command.h"

#include "commands/apply_patches_command.h"
#include "document/take_document.h"

#include <algorithm>

namespace mocap::ui {

RecordStepCommand::RecordStepCommand(TakeDocument& document, ProcessingStep step, QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_step(std::move(step))
{
}

void RecordStepCommand::redo()
{
  m_document.appendHistory(m_step);
}

void RecordStepCommand::undo()
{
  m_step = m_document.removeLastHistory();
}

ProcessingStep studioStep(const TakeDocument& document, std::string operation,
                          std::vector<std::pair<std::string, std::string>> parameters,
                          const std::vector<Eigen::Index>& markers, Eigen::Index first, Eigen::Index last,
                          std::int64_t samples)
{
  const Take& take = document.take();
  ProcessingStep step;
  step.operation = std::move(operation);
  step.parameters = std::move(parameters);
  std::vector<Eigen::Index> sorted = markers;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (static_cast<Eigen::Index>(sorted.size()) < take.markerCount())
    for (Eigen::Index m : sorted)
      step.markers.push_back(take.label(m));
  if (first <= last) {
    step.firstFrame = take.firstFrame() + first;
    step.lastFrame = take.firstFrame() + last;
  } else {
    step.firstFrame = take.firstFrame();
    step.lastFrame = take.firstFrame() + take.frameCount() - 1;
  }
  step.samples = samples;
  step.time = currentUtcTime();
  step.tool = "mocap-studio";
  return step;
}

QUndoCommand* makeRecordedEdit(TakeDocument& document, std::vector<SamplePatch> patches, const QString& text,
                               std::string operation, std::vector<std::pair<std::string, std::string>> parameters,
                               QUndoCommand* parent)
{
  std::vector<Eigen::Index> markers;
  Eigen::Index first = document.take().frameCount(), last = -1;
  std::int64_t samples = 0;
  for (const SamplePatch& patch : patches) {
    if (patch.empty())
      continue;
    markers.push_back(patch.marker);
    first = std::min(first, patch.frames.front());
    last = std::max(last, patch.frames.back());
    samples += static_cast<std::int64_t>(patch.size());
  }
  ProcessingStep step = studioStep(document, std::move(operation), std::move(parameters), markers, first, last, samples);
  auto* command = new QUndoCommand(text, parent);
  new ApplyPatchesCommand(document, std::move(patches), text, command);
  new RecordStepCommand(document, std::move(step), command);
  return command;
}

} // namespace mocap::ui
