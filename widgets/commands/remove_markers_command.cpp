#include "commands/remove_markers_command.h"

#include "document/take_document.h"

#include <QCoreApplication>

#include <algorithm>
#include <functional>

namespace mocap::ui {

RemoveMarkersCommand::RemoveMarkersCommand(TakeDocument& document, std::vector<Eigen::Index> markers,
                                           QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_markers(std::move(markers))
{
  std::sort(m_markers.begin(), m_markers.end(), std::greater<>());
  m_markers.erase(std::unique(m_markers.begin(), m_markers.end()), m_markers.end());
  if (m_markers.size() == 1)
    setText(QCoreApplication::translate("RemoveMarkersCommand", "Delete marker %1")
                .arg(QString::fromStdString(document.take().label(m_markers.front()))));
  else
    setText(QCoreApplication::translate("RemoveMarkersCommand", "Delete %1 markers").arg(m_markers.size()));
}

void RemoveMarkersCommand::redo()
{
  m_removed.clear();
  for (Eigen::Index m : m_markers)
    m_removed.emplace_back(m, m_document.removeMarker(m));
}

void RemoveMarkersCommand::undo()
{
  for (auto it = m_removed.rbegin(); it != m_removed.rend(); ++it)
    m_document.insertMarker(it->first, std::move(it->second));
  m_removed.clear();
}

} // namespace mocap::ui
