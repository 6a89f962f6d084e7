#include "commands/rebind_marker_command.h"

#include "views/face_mesh_scene.h"

#include <QCoreApplication>

namespace mocap::ui {

RebindMarkerCommand::RebindMarkerCommand(FaceMeshScene& scene, std::string label, std::optional<MarkerBinding> binding)
    : m_scene(scene), m_label(std::move(label)), m_binding(std::move(binding)), m_generation(scene.bindingGeneration())
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
  if (m_scene.bindingGeneration() != m_generation) {
    setObsolete(true);
    return;
  }
  m_binding = m_scene.rebind(m_label, std::move(m_binding));
}

} // namespace mocap::ui
