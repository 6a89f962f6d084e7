#pragma once

#include <QString>
#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace mocap::ui {

class ReferenceVideo;
class TakeDocument;
class VideoView;

/// The Reference Video dock: Add Reference Video… (any file Debian's FFmpeg decodes: MP4/H.264,
/// MOV, AVI, MKV), the video's rate, length and codec, its offset against the take (seconds,
/// typed or nudged by one video frame with the buttons or Alt+, / Alt+.), and the frame for the
/// current take frame (VideoView), decoded on a worker so scrubbing never waits. Remove closes it.
class ReferenceVideoPanel final : public QWidget
{
  Q_OBJECT

public:
  explicit ReferenceVideoPanel(TakeDocument& document, QWidget* parent = nullptr);
  ~ReferenceVideoPanel() override;

  [[nodiscard]] ReferenceVideo& video() const { return *m_video; }
  [[nodiscard]] VideoView& view() const { return *m_view; }
  /// Opens `path` as the take's reference video; returns "" or the error shown.
  QString openVideo(const QString& path);
  [[nodiscard]] QString statusText() const;

private:
  void openDialog();
  void updateInfo();

  TakeDocument& m_document;
  ReferenceVideo* m_video = nullptr;
  VideoView* m_view = nullptr;
  QLabel* m_info = nullptr;
  QDoubleSpinBox* m_offset = nullptr;
  QPushButton* m_remove = nullptr;
  QLabel* m_status = nullptr;
};

} // namespace mocap::ui
