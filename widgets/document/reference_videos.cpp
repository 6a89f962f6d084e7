#include "document/reference_videos.h"

#include "document/reference_video.h"
#include "document/take_document.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>

namespace mocap::ui {

namespace {

constexpr int kSaveDelayMs = 400;  // offsets nudged in a row are written once

std::filesystem::path toPath(const QString& path)
{
  return std::filesystem::path(path.toStdString());
}

QString fromPath(const std::filesystem::path& path)
{
  return QString::fromStdString(path.string());
}

bool sameLinks(const std::vector<ReferenceVideoLink>& a, const std::vector<ReferenceVideoLink>& b)
{
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const ReferenceVideoLink& x, const ReferenceVideoLink& y) {
    return x.path == y.path && x.relative == y.relative && x.offset == y.offset;
  });
}

} // namespace

ReferenceVideos::ReferenceVideos(TakeDocument& document, QObject* parent) : QObject(parent), m_document(document)
{
  m_saveTimer.setSingleShot(true);
  m_saveTimer.setInterval(kSaveDelayMs);
  connect(&m_saveTimer, &QTimer::timeout, this, &ReferenceVideos::save);
  connect(&document, &TakeDocument::takeReset, this, &ReferenceVideos::restore);
  connect(&document, &TakeDocument::filePathChanged, this, &ReferenceVideos::takePathChanged);
  restore();
}

ReferenceVideos::~ReferenceVideos()
{
  save();
}

ReferenceVideo& ReferenceVideos::at(int index) const
{
  return *m_entries.at(static_cast<std::size_t>(index)).video;
}

bool ReferenceVideos::isMissing(int index) const
{
  return !at(index).isOpen();
}

ReferenceVideo* ReferenceVideos::current() const
{
  return m_current >= 0 ? m_entries[static_cast<std::size_t>(m_current)].video : nullptr;
}

int ReferenceVideos::indexOf(const ReferenceVideo* video) const
{
  const auto it = std::find_if(m_entries.begin(), m_entries.end(), [video](const Entry& e) { return e.video == video; });
  return it == m_entries.end() ? -1 : static_cast<int>(it - m_entries.begin());
}

std::filesystem::path ReferenceVideos::linkBase(const QString& video) const
{
  // A video is linked relative to the take's file; an unsaved take has none yet.
  return m_document.filePath().isEmpty() ? toPath(video) : toPath(m_document.filePath());
}

int ReferenceVideos::append(const ReferenceVideoLink& link, ReferenceVideo* opened)
{
  Entry entry;
  entry.video = opened ? opened : new ReferenceVideo(m_document, this);
  entry.video->setActive(false);
  entry.stored = link;
  ReferenceVideo* video = entry.video;
  connect(video, &ReferenceVideo::changed, this, [this, video] {
    emit videoChanged(indexOf(video));
    scheduleSave();
  });
  connect(video, &ReferenceVideo::frameShown, this, [this, video] { emit videoChanged(indexOf(video)); });
  m_entries.push_back(entry);
  emit videoInserted(count() - 1);
  return count() - 1;
}

void ReferenceVideos::clear()
{
  m_current = -1;
  while (!m_entries.empty()) {
    emit videoAboutToBeRemoved(count() - 1);
    delete m_entries.back().video;
    m_entries.pop_back();
  }
}

void ReferenceVideos::setCurrentIndex(int index)
{
  m_current = index >= 0 && index < count() ? index : (m_entries.empty() ? -1 : 0);
  for (int i = 0; i < count(); ++i)
    at(i).setActive(i == m_current);  // only the current video decodes
  emit currentChanged(m_current);
}

QString ReferenceVideos::open(const QString& path)
{
  const QString absolute = QFileInfo(path).absoluteFilePath();
  for (int i = 0; i < count(); ++i)
    if (at(i).isOpen() && QFileInfo(at(i).path()).absoluteFilePath() == absolute) {
      setCurrentIndex(i);  // already linked: made current
      return {};
    }
  auto* opened = new ReferenceVideo(m_document, this);
  opened->setActive(false);
  if (const QString error = opened->open(absolute); !error.isEmpty()) {
    delete opened;
    return tr("Cannot show %1: %2").arg(QFileInfo(path).fileName(), error);
  }
  setCurrentIndex(append(linkReferenceVideo(toPath(absolute), linkBase(absolute), 0.0), opened));
  scheduleSave();
  return {};
}

void ReferenceVideos::remove(int index)
{
  if (index < 0 || index >= count())
    return;
  emit videoAboutToBeRemoved(index);
  ReferenceVideo* video = &at(index);
  m_entries.erase(m_entries.begin() + index);
  delete video;
  m_current = -1;
  setCurrentIndex(std::min(index, count() - 1));
  scheduleSave();
}

QString ReferenceVideos::locate(int index, const QString& path)
{
  if (index < 0 || index >= count())
    return {};
  ReferenceVideo& located = at(index);
  const QString absolute = QFileInfo(path).absoluteFilePath();
  if (const QString error = located.open(absolute); !error.isEmpty())  // keeps the offset
    return tr("Cannot show %1: %2").arg(QFileInfo(path).fileName(), error);
  m_entries[static_cast<std::size_t>(index)].stored =
      linkReferenceVideo(toPath(absolute), linkBase(absolute), located.offset());
  setCurrentIndex(index);
  scheduleSave();
  return {};
}

bool ReferenceVideos::openRestored(ReferenceVideo& video, const ReferenceVideoLink& link)
{
  video.setOffset(link.offset);
  const QString path = fromPath(link.path);
  const QString error = link.found ? video.open(path) : QString();
  if (!link.found)
    video.setUnavailable(path, tr("%1 is missing: the take remembers it at %2. Locate… finds it; until "
                                  "then it stays linked to the take.")
                                   .arg(QFileInfo(path).fileName(), QDir::toNativeSeparators(path)));
  else if (!error.isEmpty())
    video.setUnavailable(path, tr("Cannot show %1: %2").arg(QFileInfo(path).fileName(), error));
  return video.isOpen();
}

void ReferenceVideos::restore()
{
  save();  // a change still pending belongs to the take that was open
  m_restoring = true;
  clear();
  m_sidecarTake = m_document.filePath();
  m_sidecarReadable = true;
  m_saved.clear();
  QString problem;
  int missing = 0;
  if (!m_sidecarTake.isEmpty()) {
    try {
      m_saved = readReferenceVideoSidecar(toPath(m_sidecarTake));
    } catch (const std::exception& e) {
      m_sidecarReadable = false;
      problem = tr("The videos remembered for this take cannot be read (%1); that file is left as it is and "
                   "changes here are not remembered.")
                    .arg(QString::fromStdString(e.what()));
    }
    for (const ReferenceVideoLink& link : m_saved)
      if (!openRestored(at(append(link)), link))
        ++missing;
  }
  m_restoring = false;
  int shown = -1;
  for (int i = 0; i < count() && shown < 0; ++i)
    if (at(i).isOpen())
      shown = i;
  setCurrentIndex(shown >= 0 ? shown : 0);
  emit restored(count(), missing, problem);
}

void ReferenceVideos::takePathChanged(const QString& path)
{
  if (path == m_sidecarTake)
    return;
  // Saved under a new name: the videos go with it (relative to its folder), the old sidecar stays.
  save();
  m_sidecarTake = path;
  m_sidecarReadable = true;
  m_saved.clear();
  for (Entry& entry : m_entries)
    if (!entry.video->isOpen() && !path.isEmpty())
      entry.stored = linkReferenceVideo(entry.stored.path, toPath(path), entry.video->offset());
  scheduleSave();
}

std::vector<ReferenceVideoLink> ReferenceVideos::links() const
{
  std::vector<ReferenceVideoLink> result;
  const std::filesystem::path take = toPath(m_sidecarTake);
  for (const Entry& entry : m_entries) {
    ReferenceVideoLink link = entry.video->isOpen()
                                  ? linkReferenceVideo(toPath(entry.video->path()), take, entry.video->offset())
                                  : entry.stored;  // missing: as stored, so nothing is lost
    link.offset = entry.video->offset();
    result.push_back(std::move(link));
  }
  return result;
}

void ReferenceVideos::scheduleSave()
{
  if (!m_restoring)
    m_saveTimer.start();
}

void ReferenceVideos::save()
{
  m_saveTimer.stop();
  if (m_restoring || m_sidecarTake.isEmpty() || !m_sidecarReadable)
    return;
  std::vector<ReferenceVideoLink> current = links();
  if (sameLinks(current, m_saved))
    return;
  try {
    writeReferenceVideoSidecar(toPath(m_sidecarTake), current);
    m_saved = std::move(current);
  } catch (const std::exception& e) {
    emit saveFailed(tr("Cannot remember the videos beside the take: %1").arg(QString::fromStdString(e.what())));
  }
}

} // namespace mocap::ui
