#pragma once

#include <QUndoCommand>

#include <Eigen/Core>

#include <vector>

namespace mocap::ui {

class TakeDocument;

/// Replaces the take's head reference markers (TakeDocument::referenceMarkers): undoable, since
/// the set decides what head stabilization, layout planning and the face mesh do. Redo and undo
/// swap the stored set with the document's.
class SetReferenceMarkersCommand final : public QUndoCommand
{
public:
  SetReferenceMarkersCommand(TakeDocument& document, std::vector<Eigen::Index> markers);

  void redo() override { swap(); }
  void undo() override { swap(); }

private:
  void swap();

  TakeDocument& m_document;
  std::vector<Eigen::Index> m_markers;  // the set the next redo() or undo() puts in
};

} // namespace mocap::ui
