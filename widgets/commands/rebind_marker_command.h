#pragma once

#include "mocap/deform/mesh_binding.h"

#include <QUndoCommand>

#include <optional>
#include <string>

namespace mocap::ui {

class FaceMeshModel;

/// Binds one marker to another mesh point (or unbinds it); undo puts the old binding back (the
/// binding is swapped each time, FaceMeshModel::rebind). It lives on the document's undo stack
/// with every other edit; once the whole binding has been replaced (another mesh, binding file or
/// auto-bind) it no longer applies and becomes obsolete, so the stack drops it.
class RebindMarkerCommand final : public QUndoCommand
{
public:
  RebindMarkerCommand(FaceMeshModel& model, std::string label, std::optional<MarkerBinding> binding);

  void redo() override { swap(); }
  void undo() override { swap(); }

private:
  void swap();

  FaceMeshModel& m_model;
  std::string m_label;
  std::optional<MarkerBinding> m_binding;
  int m_generation;
};

} // namespace mocap::ui
