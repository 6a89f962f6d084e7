#include "commands/replace_take_command.h"

#include "document/take_document.h"

namespace mocap::ui {

ReplaceTakeCommand::ReplaceTakeCommand(TakeDocument& document, Take replacement, const QString& text,
                                       std::optional<ProcessingStep> step)
    : m_document(document), m_other(std::move(replacement))
{
  setText(text);
  m_other.history() = document.take().history();
  if (step)
    m_other.history().push_back(std::move(*step));
}

void ReplaceTakeCommand::swap()
{
  m_other = m_document.exchangeTake(std::move(m_other));
  emit m_document.historyChanged();
}

} // namespace mocap::ui
