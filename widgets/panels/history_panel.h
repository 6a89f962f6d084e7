#pragma once

#include <QWidget>

class QTreeWidget;
class QUndoView;

namespace mocap::ui {

class TakeDocument;

/// The History dock: the take's processing history (every applied step with its parameters,
/// markers, frames and time — what a saved take remembers, also after reopening) above this
/// session's undo stack (click an entry to undo or redo to it).
class HistoryPanel final : public QWidget
{
  Q_OBJECT

public:
  explicit HistoryPanel(TakeDocument& document, QWidget* parent = nullptr);

  /// The processing-history list (one top-level item per step, parameters as children).
  [[nodiscard]] QTreeWidget* steps() const { return m_steps; }
  [[nodiscard]] QUndoView* undoView() const { return m_undoView; }

private:
  void rebuild();

  TakeDocument& m_document;
  QTreeWidget* m_steps = nullptr;
  QUndoView* m_undoView = nullptr;
};

} // namespace mocap::ui
