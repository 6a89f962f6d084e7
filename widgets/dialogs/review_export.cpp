#include "dialogs/review_export.h"

#include "document/studio_session.h"
#include "document/take_document.h"
#include "mocap/video/review_frame.h"
#include "mocap/video/video_source.h"
#include "mocap/video/video_sync.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QImage>

#include <condition_variable>
#include <cstring>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace mocap::ui {

namespace {

/// Frames rendered but not yet encoded, at most: enough to keep the encoder busy while the next
/// frame renders, few enough to bound memory (a 1280 × 720 frame is 2.7 MB).
constexpr std::size_t kQueueLimit = 4;

VideoImage toVideoImage(const QImage& rgb888, Eigen::Index frame)
{
  VideoImage image;
  image.frame = frame;
  image.width = rgb888.width();
  image.height = rgb888.height();
  image.rgb.resize(VideoImage::byteCount(image.width, image.height));
  const std::size_t row = static_cast<std::size_t>(image.width) * 3;
  for (int y = 0; y < image.height; ++y)
    std::memcpy(image.rgb.data() + row * static_cast<std::size_t>(y), rgb888.constScanLine(y), row);
  return image;
}

/// The worker's half: the reference video, the composer and the encoder, fed rendered views
/// through a bounded queue. Errors end the worker; the UI thread sees them at its next push.
class ReviewEncoderThread
{
public:
  ReviewEncoderThread(const ReviewRequest& request, const Take& take, const ReviewLayout& layout)
      : m_layout(layout), m_takeName(request.takeName), m_firstFrame(take.firstFrame()), m_rate(take.frameRate()),
        m_writer(request.output, request.size.width(), request.size.height(), take.frameRate())
  {
    if (!request.video.isEmpty()) {
      m_video = std::make_unique<VideoSource>(request.video.toStdString());
      m_sync = {take.frameRate(), m_video->info().rate, request.videoOffset};
    }
    m_thread = std::thread([this] { run(); });
  }

  ~ReviewEncoderThread() { stop(); }
  ReviewEncoderThread(const ReviewEncoderThread&) = delete;
  ReviewEncoderThread& operator=(const ReviewEncoderThread&) = delete;

  /// Queues a rendered view, waiting while the queue is full. False once the worker has failed.
  bool push(VideoImage view)
  {
    std::unique_lock lock(m_mutex);
    m_space.wait(lock, [this] { return m_queue.size() < kQueueLimit || !m_error.isEmpty(); });
    if (!m_error.isEmpty())
      return false;
    m_queue.push_back(std::move(view));
    m_ready.notify_one();
    return true;
  }

  /// Encodes what is queued and puts the video in place; returns "" or why it failed.
  QString finish()
  {
    stop();
    if (!m_error.isEmpty())
      return m_error;
    try {
      m_writer.finish();
    } catch (const std::exception& e) {
      return QString::fromStdString(e.what());
    }
    return {};
  }

  [[nodiscard]] QString error()
  {
    std::lock_guard lock(m_mutex);
    return m_error;
  }
  [[nodiscard]] const ReviewEncoding& encoding() const { return m_writer.encoding(); }
  [[nodiscard]] long long written() const { return m_writer.framesWritten(); }

private:
  void stop()
  {
    {
      std::lock_guard lock(m_mutex);
      m_closing = true;
    }
    m_ready.notify_all();
    if (m_thread.joinable())
      m_thread.join();
  }

  void run()
  {
    for (;;) {
      VideoImage view;
      {
        std::unique_lock lock(m_mutex);
        m_ready.wait(lock, [this] { return !m_queue.empty() || m_closing; });
        if (m_queue.empty())
          return;
        view = std::move(m_queue.front());
        m_queue.pop_front();
      }
      m_space.notify_one();
      try {
        encode(view);
      } catch (const std::exception& e) {
        std::lock_guard lock(m_mutex);
        m_error = QString::fromStdString(e.what());
        m_queue.clear();
        m_space.notify_all();
        return;
      }
    }
  }

  void encode(const VideoImage& view)
  {
    ReviewCaption caption{m_takeName, reviewTimeText(m_firstFrame, view.frame, m_rate), {}};
    std::optional<VideoImage> video;
    if (m_video) {
      if (const std::optional<Eigen::Index> at = videoFrameAt(m_sync, view.frame, m_video->info().frames))
        video = m_video->frame(*at);
      else
        caption.videoNote = QCoreApplication::translate("ReviewExport", "No video at this frame").toStdString();
    }
    m_writer.write(composeReviewFrame(m_layout, view, video ? &*video : nullptr, caption));
  }

  ReviewLayout m_layout;
  std::string m_takeName;
  long long m_firstFrame;
  double m_rate;
  ReviewVideoWriter m_writer;
  std::unique_ptr<VideoSource> m_video;
  VideoSync m_sync;
  std::mutex m_mutex;
  std::condition_variable m_ready, m_space;
  std::deque<VideoImage> m_queue;
  bool m_closing = false;
  QString m_error;
  std::thread m_thread;
};

ReviewOutcome failed(QString error)
{
  ReviewOutcome outcome;
  outcome.error = std::move(error);
  return outcome;
}

} // namespace

ReviewOutcome exportReview(const ReviewSource& source, const ReviewRequest& request, const ReviewProgress& progress)
{
  QElapsedTimer clock;
  clock.start();
  if (!source.session || !source.session->document().hasTake())
    return failed(QCoreApplication::translate("ReviewExport", "There is no take to review."));
  const Take& take = source.session->document().take();
  const Eigen::Index last = request.last < 0 ? take.frameCount() - 1 : request.last;
  if (request.first < 0 || last >= take.frameCount() || request.first > last)
    return failed(QCoreApplication::translate("ReviewExport", "The frames to review are outside the take."));
  try {
    const ReviewLayout layout = reviewLayout(request.size.width(), request.size.height(), !request.video.isEmpty());
    ReviewScene scene(source, QSize(layout.view.width, layout.view.height));
    if (!scene.usable())
      return failed(QCoreApplication::translate("ReviewExport", "The 3D view cannot render here: %1").arg(scene.failureReason()));
    if (source.resetCamera)
      scene.frameCamera(request.first, last);
    ReviewEncoderThread encoder(request, take, layout);
    const long long total = last - request.first + 1;
    for (Eigen::Index frame = request.first; frame <= last; ++frame) {
      const QImage view = scene.render(frame);
      if (view.isNull())
        return failed(QCoreApplication::translate("ReviewExport", "The 3D view did not render frame %1.").arg(take.firstFrame() + frame));
      if (!encoder.push(toVideoImage(view, frame)))
        return failed(encoder.error());
      if (progress && !progress(frame - request.first + 1, total)) {
        ReviewOutcome outcome;
        outcome.cancelled = true;
        return outcome;  // the encoder's destructor drops the unfinished file
      }
    }
    ReviewOutcome outcome;
    outcome.error = encoder.finish();
    outcome.done = outcome.error.isEmpty();
    outcome.encoding = encoder.encoding();
    outcome.frames = encoder.written();
    outcome.seconds = static_cast<double>(clock.nsecsElapsed()) * 1e-9;
    return outcome;
  } catch (const std::exception& e) {
    return failed(QString::fromStdString(e.what()));
  }
}

} // namespace mocap::ui
