#pragma once

#include "mocap/model/take.h"

#include <QUndoCommand>

#include <utility>
#include <vector>

namespace mocap::ui {

class TakeDocument;

/// Deletes whole markers; undo puts each back at its old index with every sample as it was
/// (Take::removeMarker / insertMarker in core).
class RemoveMarkersCommand final : public QUndoCommand
{
public:
  RemoveMarkersCommand(TakeDocument& document, std::vector<Eigen::Index> markers, QUndoCommand* parent = nullptr);

  void redo() override;
  void undo() override;

private:
  TakeDocument& m_document;
  std::vector<Eigen::Index> m_markers;                          // descending, so indices stay valid
  std::vector<std::pair<Eigen::Index, MarkerColumn>> m_removed;  // in removal order
};

} // namespace mocap::ui
