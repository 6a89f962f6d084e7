#pragma once

#include <QUndoCommand>

#include <Eigen/Core>

#include <string>

namespace mocap::ui {

class TakeDocument;

/// Renames a marker; undo gives the old label back (the label is swapped each time).
class RenameMarkerCommand final : public QUndoCommand
{
public:
  RenameMarkerCommand(TakeDocument& document, Eigen::Index marker, std::string label);

  void redo() override { swap(); }
  void undo() override { swap(); }

private:
  void swap();

  TakeDocument& m_document;
  Eigen::Index m_marker;
  std::string m_label;
};

} // namespace mocap::ui
