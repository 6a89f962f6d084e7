#include "document/take_document.h"

#include "mocap/error.h"
#include "mocap/take_io.h"

#include <algorithm>

namespace mocap::ui {

TakeDocument::TakeDocument(QObject* parent) : QObject(parent)
{
  connect(&m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

QString TakeDocument::open(const QString& path)
{
  std::vector<std::string> warnings;
  try {
    Take loaded = readTake(path.toStdString(), &warnings);
    m_loadWarnings = std::move(warnings);
    setTake(std::move(loaded), path);
    return {};
  } catch (const std::exception& e) {  // a failed read leaves the open take as it was
    return QString::fromStdString(e.what());
  }
}

QString TakeDocument::save(const QString& path, bool markClean)
{
  try {
    writeTake(m_take, path.toStdString());
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  if (markClean) {
    m_undoStack.setClean();
    if (m_filePath != path) {
      m_filePath = path;
      emit filePathChanged(m_filePath);
    }
  }
  return {};
}

void TakeDocument::setTake(Take take, const QString& path)
{
  m_take = std::move(take);
  m_filePath = path;
  m_undoStack.clear();
  m_currentFrame = 0;
  m_selection.clear();
  m_rangeFirst = 0;
  m_rangeLast = -1;
  m_preview.clear();
  m_flags.clear();
  emit takeReset();
  emit filePathChanged(m_filePath);
  emit currentFrameChanged(m_currentFrame);
  emit selectionChanged();
}

void TakeDocument::setCurrentFrame(Eigen::Index frame)
{
  frame = std::clamp<Eigen::Index>(frame, 0, std::max<Eigen::Index>(m_take.frameCount() - 1, 0));
  if (frame == m_currentFrame)
    return;
  m_currentFrame = frame;
  emit currentFrameChanged(frame);
}

void TakeDocument::setSelection(std::vector<Eigen::Index> markers)
{
  markers.erase(std::remove_if(markers.begin(), markers.end(),
                               [this](Eigen::Index m) { return m < 0 || m >= m_take.markerCount(); }),
                markers.end());
  std::sort(markers.begin(), markers.end());
  markers.erase(std::unique(markers.begin(), markers.end()), markers.end());
  if (markers == m_selection)
    return;
  m_selection = std::move(markers);
  emit selectionChanged();
}

std::vector<SamplePatch> TakeDocument::applyPatches(std::vector<SamplePatch> patches)
{
  std::vector<Eigen::Index> markers;
  for (const SamplePatch& p : patches)
    markers.push_back(p.marker);
  std::sort(markers.begin(), markers.end());
  markers.erase(std::unique(markers.begin(), markers.end()), markers.end());
  std::vector<SamplePatch> undo = mocap::applyPatches(m_take, std::move(patches));
  emit samplesChanged(markers);
  return undo;
}

} // namespace mocap::ui

namespace mocap::ui {

std::string TakeDocument::renameMarker(Eigen::Index marker, std::string label)
{
  std::string old = m_take.label(marker);
  m_take.setLabel(marker, std::move(label));
  emit markerRenamed(marker);
  return old;
}

void TakeDocument::setRange(Eigen::Index first, Eigen::Index last)
{
  if (first > last) {
    first = 0;
    last = -1;
  } else {
    first = std::max<Eigen::Index>(first, 0);
    last = std::min<Eigen::Index>(last, m_take.frameCount() - 1);
  }
  if (first == m_rangeFirst && last == m_rangeLast)
    return;
  m_rangeFirst = first;
  m_rangeLast = last;
  emit rangeChanged();
}

} // namespace mocap::ui

namespace mocap::ui {

void TakeDocument::setPreview(std::vector<SamplePatch> patches)
{
  if (patches.empty() && m_preview.empty())
    return;
  m_preview = std::move(patches);
  emit previewChanged();
}

void TakeDocument::setFlags(std::vector<std::pair<Eigen::Index, Eigen::Index>> flags)
{
  if (flags.empty() && m_flags.empty())
    return;
  m_flags = std::move(flags);
  emit flagsChanged();
}

} // namespace mocap::ui
