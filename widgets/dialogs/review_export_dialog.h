#pragma once

#include "dialogs/review_export.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QSpinBox;

namespace mocap::ui {

class TakeDocument;

/// File ▸ Export Review Video…: where the video goes, its size, the frames (the take, or the range
/// selected on the curves) and whether the reference video is drawn beside the 3D view. The last
/// folder and size are remembered.
class ReviewExportDialog final : public QDialog
{
  Q_OBJECT

public:
  /// `videoPath` and `videoOffset`: the reference video open beside the take ("" when none).
  ReviewExportDialog(const TakeDocument& document, const QString& videoPath, double videoOffset,
                     QWidget* parent = nullptr);

  /// The export the dialog describes (valid after it was accepted).
  [[nodiscard]] ReviewRequest request() const;

private:
  void browse();
  void accept() override;

  const TakeDocument& m_document;
  QString m_videoPath;
  double m_videoOffset;
  QLineEdit* m_output = nullptr;
  QComboBox* m_size = nullptr;
  QSpinBox* m_first = nullptr;
  QSpinBox* m_last = nullptr;
  QCheckBox* m_withVideo = nullptr;
};

} // namespace mocap::ui
