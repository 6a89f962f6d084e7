#include "commands/insert_marker_command.h"

#include "document/take_document.h"

namespace mocap::ui {

InsertMarkerCommand::InsertMarkerCommand(TakeDocument& document, MarkerColumn column, const QString& text)
    : m_document(document), m_index(document.take().markerCount()), m_column(std::move(column))
{
  setText(text);
}

void InsertMarkerCommand::redo()
{
  m_document.insertMarker(m_index, std::move(m_column));
}

void InsertMarkerCommand::undo()
{
  m_column = m_document.removeMarker(m_index);
}

} // namespace mocap::ui
