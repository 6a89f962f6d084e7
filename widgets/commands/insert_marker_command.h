#pragma once

#include "mocap/model/take.h"

#include <QUndoCommand>

namespace mocap::ui {

class TakeDocument;

/// Adds a marker built in code (e.g. an averaged, virtual marker) at the end of the take; undo
/// removes it again.
class InsertMarkerCommand final : public QUndoCommand
{
public:
  InsertMarkerCommand(TakeDocument& document, MarkerColumn column, const QString& text);

  void redo() override;
  void undo() override;

private:
  TakeDocument& m_document;
  Eigen::Index m_index;
  MarkerColumn m_column;  // empty while the marker is in the take
};

} // namespace mocap::ui
