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
/// reads the header and one frame; the worker then checks the frame timestamps first (info()
/// changes when the file's frame rate varies: it then maps by them, see timesChecked()).
/// The video can be held at one of its frames while the user finds the same moment in the take
/// (then syncTo lines the two up). A hidden video (setActive(false)) decodes nothing.
class ReferenceVideo final : public QObject
{
  Q_OBJECT

public:
  explicit ReferenceVideo(TakeDocument& document, QObject* parent = nullptr);
  ~ReferenceVideo() override;

  /// Opens `path` (replacing any video); returns "" or why it cannot be shown.
  QString open(const QString& path);
  void close();
  /// Names a video that cannot be opened (a missing file): closed, with `path` and `why` kept to show.
  void setUnavailable(const QString& path, const QString& why);
  [[nodiscard]] bool isOpen() const { return m_info.frames > 0; }
  [[nodiscard]] const QString& path() const { return m_path; }
  [[nodiscard]] const VideoInfo& info() const { return m_info; }
  /// Whether the worker has checked the frame timestamps of the open video (info() is final).
  [[nodiscard]] bool timesChecked() const { return m_timesChecked; }

  void setOffset(double seconds);
  [[nodiscard]] double offset() const { return m_offset; }
  /// Moves the offset by `frames` video frames (a nudge while lining up the video).
  void nudge(int frames);

  /// Holds the video at `frame` (clamped to the video) whatever the take's frame, or follows the
  /// take again (nullopt).
  void hold(std::optional<Eigen::Index> frame);
  [[nodiscard]] std::optional<Eigen::Index> heldFrame() const { return m_held; }
  /// Sets the offset that shows video frame `videoFrame` at take frame `takeFrame` (by the
  /// frame's timestamp in a variable-frame-rate video) and follows the take again.
  void syncTo(Eigen::Index takeFrame, Eigen::Index videoFrame);
  /// Video frame `frame`'s time (s): its timestamp, or frame / rate.
  [[nodiscard]] double timeOf(Eigen::Index frame) const;

  /// Only an active video decodes (the dock shows one video at a time); activating asks for the
  /// current frame.
  void setActive(bool active);
  [[nodiscard]] bool isActive() const { return m_active; }

  /// The held frame, else the video frame for the document's current frame; nullopt outside the video.
  [[nodiscard]] std::optional<Eigen::Index> wantedFrame() const;
  /// The video frame for take frame `takeFrame` with the current offset, or nullopt outside the video.
  [[nodiscard]] std::optional<Eigen::Index> frameForTake(Eigen::Index takeFrame) const;
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
  // Results of the worker of opening `generation` (dropped when the video changed since).
  void deliverFrom(unsigned generation, QImage image, Eigen::Index frame, QString error);
  void checked(unsigned generation, VideoInfo info, QString error);
  void decodeLoop(std::unique_ptr<VideoSource> source);
  void stopWorker();

  TakeDocument& m_document;
  QString m_path;
  VideoInfo m_info;
  bool m_timesChecked = false;
  unsigned m_generation = 0;  // which opening the worker's results belong to
  double m_offset = 0.0;
  std::optional<Eigen::Index> m_held;
  bool m_active = true;
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
