#include "commands/rebind_marker_command.h"

#include "document/face_mesh_model.h"

#include <QCoreApplication>

namespace mocap::ui {

RebindMarkerCommand::RebindMarkerCommand(FaceMeshModel& model, std::string label, std::optional<MarkerBinding> binding)
    : m_model(model), m_label(std::move(label)), m_binding(std::move(binding)), m_generation(model.bindingGeneration())
{
  const QString name = QString::fromStdString(m_label);
  if (!m_binding)
    setText(QCoreApplication::translate("RebindMarkerCommand", "Unbind %1").arg(name));
  else if (m_binding->point.isVertex())
    setText(QCoreApplication::translate("RebindMarkerCommand", "Bind %1 to vertex %2")
                .arg(name)
                .arg(static_cast<qlonglong>(m_binding->point.vertices[0])));
  else
    setText(QCoreApplication::translate("RebindMarkerCommand", "Bind %1 to the surface").arg(name));
}

void RebindMarkerCommand::swap()
{
  if (m_model.bindingGeneration() != m_generation) {
    setObsolete(true);
    return;
  }
  m_binding = m_model.rebind(m_label, std::move(m_binding));
}

} // namespace mocap::ui
