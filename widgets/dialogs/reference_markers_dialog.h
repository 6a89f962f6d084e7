#pragma once

#include <QDialog>

#include <Eigen/Core>

#include <vector>

class QDialogButtonBox;
class QLabel;
class QListWidget;

namespace mocap::ui {

class TakeDocument;

/// Marker ▸ Reference Markers…: the one place where the take's head reference markers are shown
/// and chosen — every marker with a check box, checked when it is in the set (for a take without
/// one, when the document proposes it: TakeDocument::proposedReferenceMarkers). Guess proposes
/// guessHeadReferenceMarkers again, Use Selection takes the selected markers, Clear empties the
/// set. OK is refused for one or two markers (a head pose needs three, or none for no
/// stabilization). The caller pushes the result as a command; the dialog changes nothing itself.
class ReferenceMarkersDialog final : public QDialog
{
  Q_OBJECT

public:
  explicit ReferenceMarkersDialog(const TakeDocument& document, QWidget* parent = nullptr);

  /// The checked markers, ascending.
  [[nodiscard]] std::vector<Eigen::Index> chosen() const;
  /// Checks exactly `markers`.
  void setChosen(const std::vector<Eigen::Index>& markers);
  [[nodiscard]] QListWidget* list() const { return m_list; }

private:
  void updateSummary();

  const TakeDocument& m_document;
  QListWidget* m_list = nullptr;
  QLabel* m_summary = nullptr;
  QDialogButtonBox* m_buttons = nullptr;
};

} // namespace mocap::ui
