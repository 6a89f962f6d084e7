#include "commands/set_reference_markers_command.h"

#include "document/take_document.h"

#include <QCoreApplication>

namespace mocap::ui {

SetReferenceMarkersCommand::SetReferenceMarkersCommand(TakeDocument& document, std::vector<Eigen::Index> markers)
    : m_document(document), m_markers(std::move(markers))
{
  setText(QCoreApplication::translate("SetReferenceMarkersCommand", "Set %n reference marker(s)", nullptr,
                                      static_cast<int>(m_markers.size())));
}

void SetReferenceMarkersCommand::swap()
{
  const bool wasSaved = m_document.referenceMarkersSaved();
  m_markers = m_document.setReferenceMarkers(std::move(m_markers), m_saved);
  m_saved = wasSaved;
}

} // namespace mocap::ui
