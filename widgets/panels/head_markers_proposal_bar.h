#pragma once

#include <Eigen/Core>

#include <QFrame>

#include <vector>

class QLabel;

namespace mocap::ui {

class TakeDocument;

/// The one question a take without saved or root*/head* labelled head markers asks: a bar at the
/// top of the window, "Head markers guessed: A, B, C, D — Accept / Choose…", showing the most
/// rigid cluster the document proposes (TakeDocument::proposedReferenceMarkers). Non-blocking:
/// work goes on while it shows. It asks once per take: any answer (Accept, Choose…, the close
/// button, or a set chosen elsewhere) hides it until another take is opened. Accept and Choose…
/// are requests the main window carries out (an undoable SetReferenceMarkersCommand, the
/// Reference Markers dialog).
class HeadMarkersProposalBar final : public QFrame
{
  Q_OBJECT

public:
  explicit HeadMarkersProposalBar(const TakeDocument& document, QWidget* parent = nullptr);

  /// What the bar says, e.g. "Head markers guessed: h1, h2, h3, h4".
  [[nodiscard]] QString text() const;

signals:
  /// Accept: make `markers` (the proposal shown) the take's reference markers.
  void acceptRequested(const std::vector<Eigen::Index>& markers);
  /// Choose…: open the Reference Markers dialog.
  void chooseRequested();

private:
  void refresh();
  void answer();

  const TakeDocument& m_document;
  QLabel* m_text = nullptr;
  std::vector<Eigen::Index> m_shown;
};

} // namespace mocap::ui
