#include "commands/rename_marker_command.h"

#include "document/take_document.h"

#include <QCoreApplication>

namespace mocap::ui {

RenameMarkerCommand::RenameMarkerCommand(TakeDocument& document, Eigen::Index marker, std::string label)
    : m_document(document), m_marker(marker), m_label(std::move(label))
{
  setText(QCoreApplication::translate("RenameMarkerCommand", "Rename %1 to %2")
              .arg(QString::fromStdString(document.take().label(marker)), QString::fromStdString(m_label)));
}

void RenameMarkerCommand::swap()
{
  m_label = m_document.renameMarker(m_marker, m_label);
}

} // namespace mocap::ui
