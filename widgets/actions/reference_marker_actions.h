#pragma once

#include <Eigen/Core>

#include <QObject>
#include <QString>

#include <vector>

class QWidget;

namespace mocap::ui {

class TakeDocument;

/// The take's head reference markers as menu operations, each one undoable
/// SetReferenceMarkersCommand on the document's stack: the one editor (Marker ▸ Reference
/// Markers…, which every panel sends the user to), the selection made the set, and a proposed
/// set accepted. An edit that changes nothing pushes nothing and says so in message().
class ReferenceMarkerActions final : public QObject
{
  Q_OBJECT

public:
  /// `dialogParent` parents the editor dialog.
  ReferenceMarkerActions(TakeDocument& document, QWidget& dialogParent, QObject* parent = nullptr);

  /// Pushes SetReferenceMarkersCommand unless `markers` (any order, repeats ignored) is the
  /// current set. Returns whether it did. O(n log n).
  bool change(std::vector<Eigen::Index> markers);
  /// Marker ▸ Reference Markers…: the editor dialog; its choice is one undoable edit.
  void edit();
  /// Marker ▸ Set Selected as Reference Markers: at least three selected markers become the set.
  void setSelected();
  /// The head markers proposed for a take without any (HeadMarkersProposalBar) become the set.
  void acceptProposed(const std::vector<Eigen::Index>& markers);

signals:
  /// What an edit did or why it did nothing, for the status bar.
  void message(const QString& text, int timeoutMs);

private:
  TakeDocument& m_document;
  QWidget& m_dialogParent;
};

} // namespace mocap::ui
