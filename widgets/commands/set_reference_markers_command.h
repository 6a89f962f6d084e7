#pragma once

#include <QUndoCommand>

#include <Eigen/Core>

#include <vector>

namespace mocap::ui {

class TakeDocument;

/// Replaces the take's head reference markers (TakeDocument::referenceMarkers): undoable, since
/// the set decides what head stabilization, layout planning and the face mesh do. Redo and undo
/// swap the stored set with the document's, and whether the take saves it (a set only named by
/// root*/head* labels is not saved until chosen, and undo brings that back).
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
  bool m_saved = true;                  // whether that set is the take's own (saved with it)
};

} // namespace mocap::ui
