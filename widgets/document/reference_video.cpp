#include "document/reference_video.h"

#include "document/take_document.h"

#include <QMetaObject>
#include <QPointer>

#include <algorithm>
#include <cmath>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace mocap::ui {

namespace {
constexpr int kLookAhead = 12;         // frames decoded ahead of the newest request
constexpr std::size_t kCacheSize = 48; // decoded frames kept (the farthest from the request go first)

/// Decoding yields to the UI thread: on Linux a thread has its own nice value, and the threads it
/// starts inherit it. Elsewhere a no-op.
void lowerThisThreadsPriority()
{
#ifdef __linux__
  (void)setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#endif
}

QImage toImage(const VideoImage& decoded)
{
  // Converted here, on the worker, to the format QPainter scales fastest (and owning its pixels:
  // `decoded` goes away); an RGB888 image would be converted on the UI thread at every paint.
  return QImage(decoded.rgb.data(), decoded.width, decoded.height, decoded.width * 3, QImage::Format_RGB888)
      .convertToFormat(QImage::Format_RGB32);
}
} // namespace

ReferenceVideo::ReferenceVideo(TakeDocument& document, QObject* parent) : QObject(parent), m_document(document)
{
  connect(&document, &TakeDocument::currentFrameChanged, this, &ReferenceVideo::request);
  connect(&document, &TakeDocument::takeReset, this, &ReferenceVideo::request);
}

ReferenceVideo::~ReferenceVideo()
{
  stopWorker();
}

QString ReferenceVideo::open(const QString& path)
{
  std::unique_ptr<VideoSource> source;
  try {
    // The header and one frame here; the worker checks the timestamps (it may decode a group of pictures).
    source = std::make_unique<VideoSource>(path.toStdString(), VideoSource::FrameTimes::Later);
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  stopWorker();
  m_path = path;
  m_info = source->info();
  m_timesChecked = false;
  ++m_generation;
  m_held.reset();
  m_image = QImage();
  m_imageFrame = -1;
  m_error.clear();
  {
    const std::lock_guard lock(m_mutex);
    m_stop = false;
    m_request = -1;
    m_ahead = -1;
    m_aheadLeft = 0;
    m_cache.clear();
  }
  m_worker = std::thread([this, s = std::move(source)]() mutable { decodeLoop(std::move(s)); });
  emit changed();
  request();
  return {};
}

void ReferenceVideo::close()
{
  setUnavailable(QString(), QString());
}

void ReferenceVideo::setUnavailable(const QString& path, const QString& why)
{
  stopWorker();
  m_path = path;
  m_info = {};
  m_timesChecked = false;
  ++m_generation;
  m_held.reset();
  m_image = QImage();
  m_imageFrame = -1;
  m_error = why;
  emit changed();
  emit frameShown();
}

void ReferenceVideo::stopWorker()
{
  if (!m_worker.joinable())
    return;
  {
    const std::lock_guard lock(m_mutex);
    m_stop = true;
  }
  m_wake.notify_all();
  m_worker.join();
}

void ReferenceVideo::setOffset(double seconds)
{
  if (!std::isfinite(seconds) || seconds == m_offset)
    return;
  m_offset = seconds;
  emit changed();
  request();
}

void ReferenceVideo::nudge(int frames)
{
  if (isOpen())
    setOffset(m_offset + static_cast<double>(frames) / m_info.rate);
}

void ReferenceVideo::hold(std::optional<Eigen::Index> frame)
{
  if (frame && isOpen())
    frame = std::clamp<Eigen::Index>(*frame, 0, m_info.frames - 1);
  else
    frame.reset();
  if (frame == m_held)
    return;
  m_held = frame;
  emit changed();
  request();
}

void ReferenceVideo::syncTo(Eigen::Index takeFrame, Eigen::Index videoFrame)
{
  if (!isOpen() || m_document.take().frameRate() <= 0.0)
    return;
  const VideoSync sync{m_document.take().frameRate(), m_info.rate, m_offset};
  const Eigen::Index frame = std::clamp<Eigen::Index>(videoFrame, 0, m_info.frames - 1);
  m_held.reset();
  const double offset = m_info.variableRate ? offsetMatching(sync, takeFrame, frame, m_info.frameTimes)
                                            : offsetMatching(sync, takeFrame, frame);
  if (offset == m_offset)
    emit changed();  // the hold ended
  setOffset(offset);
  request();
}

double ReferenceVideo::timeOf(Eigen::Index frame) const
{
  if (m_info.variableRate && frame >= 0 && static_cast<std::size_t>(frame) < m_info.frameTimes.size())
    return m_info.frameTimes[static_cast<std::size_t>(frame)];
  return m_info.rate > 0.0 ? static_cast<double>(frame) / m_info.rate : 0.0;
}

void ReferenceVideo::setActive(bool active)
{
  if (active == m_active)
    return;
  m_active = active;
  if (m_active)
    request();
}

std::optional<Eigen::Index> ReferenceVideo::frameForTake(Eigen::Index takeFrame) const
{
  if (!isOpen() || m_document.take().frameRate() <= 0.0)
    return std::nullopt;
  const VideoSync sync{m_document.take().frameRate(), m_info.rate, m_offset};
  return m_info.variableRate ? videoFrameAt(sync, takeFrame, m_info.frameTimes)
                             : videoFrameAt(sync, takeFrame, m_info.frames);
}

std::optional<Eigen::Index> ReferenceVideo::wantedFrame() const
{
  if (m_held && isOpen())
    return m_held;
  return frameForTake(m_document.currentFrame());
}

void ReferenceVideo::request()
{
  if (!m_active)
    return;
  const std::optional<Eigen::Index> wanted = wantedFrame();
  if (!wanted) {
    if (isOpen())
      emit frameShown();  // the view says "no video at this frame"
    return;
  }
  if (*wanted == m_imageFrame)
    return;
  QImage cached;
  {
    const std::lock_guard lock(m_mutex);
    if (const auto hit = m_cache.find(*wanted); hit != m_cache.end()) {
      cached = hit->second;
      m_ahead = *wanted + 1;  // keep decoding ahead of where playback is
      m_aheadLeft = kLookAhead;
    } else {
      m_request = *wanted;
    }
  }
  m_wake.notify_all();
  if (!cached.isNull())
    deliver(std::move(cached), *wanted, QString());
}

bool ReferenceVideo::isCached(Eigen::Index frame)
{
  const std::lock_guard lock(m_mutex);
  return m_cache.count(frame) > 0;
}

void ReferenceVideo::deliver(QImage image, Eigen::Index frame, QString error)
{
  m_error = std::move(error);
  if (!image.isNull()) {
    m_image = std::move(image);
    m_imageFrame = frame;
  }
  emit frameShown();
}

void ReferenceVideo::deliverFrom(unsigned generation, QImage image, Eigen::Index frame, QString error)
{
  if (generation == m_generation)  // else it is of a video closed since
    deliver(std::move(image), frame, std::move(error));
}

void ReferenceVideo::checked(unsigned generation, VideoInfo info, QString error)
{
  if (generation != m_generation)
    return;
  m_timesChecked = true;
  if (!error.isEmpty()) {  // nothing decodes after all
    setUnavailable(m_path, error);
    return;
  }
  const bool same = info.frames == m_info.frames && info.variableRate == m_info.variableRate;
  m_info = std::move(info);
  if (m_held)
    m_held = std::min(*m_held, m_info.frames - 1);
  emit changed();
  if (!same) {
    m_imageFrame = -1;  // the mapping changed: ask again
    request();
  }
}

void ReferenceVideo::decodeLoop(std::unique_ptr<VideoSource> source)
{
  const QPointer<ReferenceVideo> self(this);
  const unsigned generation = m_generation;  // set before the thread started
  lowerThisThreadsPriority();
  QString timesError;
  try {
    // Reopened here: FFmpeg's decoding threads start with the decoder, and so share this thread's
    // lower priority (the UI thread goes first when the cores are busy).
    const std::filesystem::path path = source->path();
    source.reset();
    source = std::make_unique<VideoSource>(path, VideoSource::FrameTimes::Later);
    source->checkFrameTimes();
  } catch (const std::exception& e) {
    timesError = QString::fromStdString(e.what());
  }
  QMetaObject::invokeMethod(
      this,
      [self, generation, info = source ? source->info() : VideoInfo{}, timesError]() mutable {
        if (self)
          self->checked(generation, std::move(info), std::move(timesError));
      },
      Qt::QueuedConnection);
  if (!timesError.isEmpty())
    return;
  const Eigen::Index frames = source->info().frames;
  while (true) {
    Eigen::Index frame = -1;
    bool asked = false;  // a request (delivered) rather than a look-ahead (cached only)
    {
      std::unique_lock lock(m_mutex);
      m_wake.wait(lock, [&] { return m_stop || m_request >= 0 || (m_aheadLeft > 0 && m_ahead < frames); });
      if (m_stop)
        return;
      if (m_request >= 0) {
        frame = m_request;
        m_request = -1;  // taken; a newer request replaces it while this one decodes
        asked = true;
        m_ahead = frame + 1;
        m_aheadLeft = kLookAhead;
      } else {
        frame = m_ahead++;
        --m_aheadLeft;
        if (m_cache.count(frame) > 0)
          continue;
      }
    }
    QImage image;
    QString error;
    try {
      image = toImage(source->frame(frame));
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    {
      const std::lock_guard lock(m_mutex);
      if (!image.isNull())
        m_cache[frame] = image;
      while (m_cache.size() > kCacheSize) {  // drop the frame farthest from this one
        const auto first = m_cache.begin(), last = std::prev(m_cache.end());
        m_cache.erase(frame - first->first > last->first - frame ? first : last);
      }
    }
    if (!asked)
      continue;
    QMetaObject::invokeMethod(
        this,
        [self, generation, image = std::move(image), frame, error = std::move(error)]() mutable {
          if (self)
            self->deliverFrom(generation, std::move(image), frame, std::move(error));
        },
        Qt::QueuedConnection);
  }
}

} // namespace mocap::ui
