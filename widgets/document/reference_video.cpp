#include "document/reference_video.h"

#include "document/take_document.h"

#include <QMetaObject>
#include <QPointer>

#include <cmath>

namespace mocap::ui {

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
    source = std::make_unique<VideoSource>(path.toStdString());
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  stopWorker();
  m_path = path;
  m_info = source->info();
  m_image = QImage();
  m_imageFrame = -1;
  m_error.clear();
  {
    const std::lock_guard lock(m_mutex);
    m_stop = false;
    m_request = -1;
  }
  m_worker = std::thread([this, s = std::move(source)]() mutable { decodeLoop(std::move(s)); });
  emit changed();
  request();
  return {};
}

void ReferenceVideo::close()
{
  stopWorker();
  m_path.clear();
  m_info = {};
  m_image = QImage();
  m_imageFrame = -1;
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

std::optional<Eigen::Index> ReferenceVideo::wantedFrame() const
{
  if (!isOpen() || m_document.take().frameRate() <= 0.0)
    return std::nullopt;
  return videoFrameAt({m_document.take().frameRate(), m_info.rate, m_offset}, m_document.currentFrame(), m_info.frames);
}

void ReferenceVideo::request()
{
  const std::optional<Eigen::Index> wanted = wantedFrame();
  if (!wanted) {
    if (isOpen())
      emit frameShown();  // the view says "no video at this frame"
    return;
  }
  if (*wanted == m_imageFrame)
    return;
  {
    const std::lock_guard lock(m_mutex);
    m_request = *wanted;
  }
  m_wake.notify_all();
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

void ReferenceVideo::decodeLoop(std::unique_ptr<VideoSource> source)
{
  const QPointer<ReferenceVideo> self(this);
  while (true) {
    Eigen::Index frame = -1;
    {
      std::unique_lock lock(m_mutex);
      m_wake.wait(lock, [this] { return m_stop || m_request >= 0; });
      if (m_stop)
        return;
      frame = m_request;
      m_request = -1;  // taken; a newer request replaces it while this one decodes
    }
    QImage image;
    QString error;
    try {
      const VideoImage decoded = source->frame(frame);
      image = QImage(decoded.rgb.data(), decoded.width, decoded.height, decoded.width * 3, QImage::Format_RGB888)
                  .copy();  // own the pixels: `decoded` goes away
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    QMetaObject::invokeMethod(
        this,
        [self, image = std::move(image), frame, error = std::move(error)]() mutable {
          if (self)
            self->deliver(std::move(image), frame, std::move(error));
        },
        Qt::QueuedConnection);
  }
}

} // namespace mocap::ui
