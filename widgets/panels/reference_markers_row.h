#pragma once

#include <QString>
#include <QWidget>

class QLabel;
class QPushButton;

namespace mocap::ui {

class TakeDocument;

/// The take's head reference markers as a panel shows them: read only, with an Edit… button that
/// asks for the one editor (Marker ▸ Reference Markers…, wired by the main window). Follows the
/// document (a new take, an edit of the set, a renamed marker).
class ReferenceMarkersRow final : public QWidget
{
  Q_OBJECT

public:
  /// `purpose` says in the tooltip what the panel does with the markers.
  ReferenceMarkersRow(const TakeDocument& document, const QString& purpose, QWidget* parent = nullptr);

  /// What the row shows, e.g. "root-1, root-2, root-3 (3)".
  [[nodiscard]] QString text() const;

signals:
  void editRequested();

private:
  void refresh();

  const TakeDocument& m_document;
  QLabel* m_labels = nullptr;
  QPushButton* m_edit = nullptr;
};

} // namespace mocap::ui
