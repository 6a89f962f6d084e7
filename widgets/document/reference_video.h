#pragma once

#include "mocap/video/video_source.h"
#include "mocap/video/video_sync.h"

#include <QImage>
#include <QObject>
#include <QString>

#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace mocap::ui {

class TakeDocument;

/// A reference video beside the open take: the file, its sync offset (video time = (take frame
/// − first) / take rate + offset), and a decoder thread that turns the document's current frame
/// into the matching video frame. Requests never wait: the UI asks for a frame and keeps the last
/// delivered one until the worker has decoded the newest request (older requests it has not
/// started are dropped, so scrubbing never queues work). When idle the worker decodes ahead of the
/// last request into a small cache, so playback finds its next frames already decoded. Opening
/// reads only the header.
class ReferenceVideo final : public QObject
{
  Q_OBJECT

public:
  explicit ReferenceVideo(TakeDocument& document, QObject* parent = nullptr);
  ~ReferenceVideo() override;

  /// Opens `path` (replacing any video); returns "" or why it cannot be shown.
  QString open(const QString& path);
  void close();
  [[nodiscard]] bool isOpen() const { return m_info.frames > 0; }
  [[nodiscard]] const QString& path() const { return m_path; }
  [[nodiscard]] const VideoInfo& info() const { return m_info; }

  void setOffset(double seconds);
  [[nodiscard]] double offset() const { return m_offset; }
  /// Moves the offset by `frames` video frames (a nudge while lining up the video).
  void nudge(int frames);

  /// The video frame for the document's current frame, or nullopt outside the video.
  [[nodiscard]] std::optional<Eigen::Index> wantedFrame() const;
  /// The last decoded image and its video frame (−1: none yet).
  [[nodiscard]] const QImage& image() const { return m_image; }
  [[nodiscard]] Eigen::Index imageFrame() const { return m_imageFrame; }
  /// Whether video frame `frame` is decoded and waiting in the look-ahead cache.
  [[nodiscard]] bool isCached(Eigen::Index frame);
  /// Why the last decode failed, or "".
  [[nodiscard]] const QString& error() const { return m_error; }

signals:
  /// A video was opened or closed, or the offset changed.
  void changed();
  /// A decoded frame arrived (or the wanted frame left the video).
  void frameShown();

private:
  void request();
  void deliver(QImage image, Eigen::Index frame, QString error);
  void decodeLoop(std::unique_ptr<VideoSource> source);
  void stopWorker();

  TakeDocument& m_document;
  QString m_path;
  VideoInfo m_info;
  double m_offset = 0.0;
  QImage m_image;
  Eigen::Index m_imageFrame = -1;
  QString m_error;

  // Shared with the decoder thread.
  std::mutex m_mutex;
  std::condition_variable m_wake;
  Eigen::Index m_request = -1;  // the newest frame asked for; −1: none
  Eigen::Index m_ahead = -1;    // the next frame to decode ahead; −1: none
  int m_aheadLeft = 0;          // how many more to decode ahead before idling
  std::map<Eigen::Index, QImage> m_cache;
  bool m_stop = false;
  std::thread m_worker;
};

} // namespace mocap::ui
