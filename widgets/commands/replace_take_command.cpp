#include "commands/replace_take_command.h"

#include "document/take_document.h"

namespace mocap::ui {

ReplaceTakeCommand::ReplaceTakeCommand(TakeDocument& document, Take replacement, const QString& text)
    : m_document(document), m_other(std::move(replacement))
{
  setText(text);
}

void ReplaceTakeCommand::swap()
{
  m_other = m_document.exchangeTake(std::move(m_other));
}

} // namespace mocap::ui
