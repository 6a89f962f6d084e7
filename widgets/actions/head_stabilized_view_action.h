#pragma once

#include <QObject>
#include <QString>

class QAction;
class QWidget;

namespace mocap::ui {

class TakeDocument;
class ViewState;

/// View ▸ Head-Stabilized View (Ctrl+B): the 3D view shows the markers in the head frame of the
/// take's reference markers, a view setting (the session's ViewState::headReference, which the
/// views observe; the take is not changed). Turning it on needs at
/// least three reference markers that carry a head pose (else a warning says why and it stays
/// off); while on, the view follows the set as it changes (edited, a marker removed or inserted,
/// another take) or goes back to the lab frame, saying so.
class HeadStabilizedViewAction final : public QObject
{
  Q_OBJECT

public:
  /// Create it after the views, so its handlers run after the views' own (which drop the old
  /// indices). `dialogParent` parents the warning.
  HeadStabilizedViewAction(TakeDocument& document, ViewState& view, QWidget& dialogParent, QObject* parent = nullptr);

  /// The checkable menu action.
  [[nodiscard]] QAction* action() const { return m_action; }
  void setOn(bool on);

signals:
  /// What changed, for the status bar.
  void message(const QString& text, int timeoutMs);

private:
  void followReferenceMarkers();
  /// Why the take's reference markers cannot carry a head pose; empty when they can.
  [[nodiscard]] QString headPoseProblem() const;

  TakeDocument& m_document;
  ViewState& m_view;
  QWidget& m_dialogParent;
  QAction* m_action = nullptr;
};

} // namespace mocap::ui
