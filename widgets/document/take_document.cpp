#include "document/take_document.h"

#include "mocap/base/error.h"
#include "mocap/cleaning/head_marker_labels.h"
#include "mocap/cleaning/head_stabilization.h"
#include "mocap/model/provenance.h"
#include "mocap/io/take_io.h"
#include "mocap/model/marker_points.h"

#include <algorithm>

namespace mocap::ui {

TakeDocument::TakeDocument(QObject* parent) : QObject(parent)
{
  connect(&m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
  // Connected before any view, so a view asking for the head motion on these signals gets a fresh one.
  const auto forgetHeadMotions = [this] { m_headMotions.clear(); };
  connect(this, &TakeDocument::takeReset, this, forgetHeadMotions);
  connect(this, &TakeDocument::samplesChanged, this, forgetHeadMotions);
  connect(this, &TakeDocument::markersChanged, this, forgetHeadMotions);
}

TakeDocument::ReadResult TakeDocument::read(const QString& path)
{
  ReadResult result;
  result.take = readTake(path.toStdString(), &result.warnings, &result.dataLoss);
  return result;
}

void TakeDocument::open(ReadResult read, const QString& path)
{
  setTake(std::move(read.take), path);
  m_loadWarnings = std::move(read.warnings);
  m_dataLoss = std::move(read.dataLoss);
}

QString TakeDocument::open(const QString& path)
{
  try {
    open(read(path), path);
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
  m_readFilePath = path;
  m_loadWarnings.clear();
  m_dataLoss.clear();
  m_undoStack.clear();
  m_currentFrame = 0;
  m_selection.clear();
  m_rangeFirst = 0;
  m_rangeLast = -1;
  m_preview.clear();
  m_flags.clear();
  m_hidden.assign(static_cast<std::size_t>(m_take.markerCount()), false);
  loadReferenceMarkers();
  emit takeReset();
  emit historyChanged();
  emit filePathChanged(m_filePath);
  emit currentFrameChanged(m_currentFrame);
  emit selectionChanged();
}

void TakeDocument::appendHistory(ProcessingStep step)
{
  m_take.history().push_back(std::move(step));
  emit historyChanged();
}

ProcessingStep TakeDocument::removeLastHistory()
{
  if (m_take.history().empty())
    return {};
  ProcessingStep step = std::move(m_take.history().back());
  m_take.history().pop_back();
  emit historyChanged();
  return step;
}

void TakeDocument::setCurrentFrame(Eigen::Index frame)
{
  frame = std::clamp<Eigen::Index>(frame, 0, std::max<Eigen::Index>(m_take.frameCount() - 1, 0));
  if (frame == m_currentFrame)
    return;
  m_currentFrame = frame;
  emit currentFrameChanged(frame);
}

int TakeDocument::selectLabels(const QStringList& labels)
{
  std::vector<Eigen::Index> markers;
  for (const QString& label : labels)
    if (const auto index = m_take.markerIndex(label.trimmed().toStdString()))
      markers.push_back(*index);
  const int found = static_cast<int>(markers.size());
  setSelection(std::move(markers));
  return found;
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
  if (isReferenceMarker(marker)) {
    storeReferenceMarkers();         // saved by label: the new one
    emit referenceMarkersChanged();  // the set's labels, as the panels show them, changed
  }
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

namespace mocap::ui {

MarkerColumn TakeDocument::removeMarker(Eigen::Index marker)
{
  MarkerColumn column = m_take.removeMarker(marker);
  m_hidden.erase(m_hidden.begin() + static_cast<std::ptrdiff_t>(marker));
  std::vector<Eigen::Index> selection;
  for (Eigen::Index m : m_selection)
    if (m != marker)
      selection.push_back(m > marker ? m - 1 : m);
  m_selection = std::move(selection);
  m_preview.clear();  // previews and flags index markers; the panels recompute them
  m_flags.clear();
  const bool referenceChanged = referenceMarkerRemoved(marker, column.label);
  storeReferenceMarkers();
  emit markersChanged();
  emit selectionChanged();
  if (referenceChanged)
    emit referenceMarkersChanged();
  return column;
}

void TakeDocument::insertMarker(Eigen::Index marker, MarkerColumn column)
{
  m_take.insertMarker(marker, std::move(column));
  m_hidden.insert(m_hidden.begin() + static_cast<std::ptrdiff_t>(marker), false);
  for (Eigen::Index& m : m_selection)
    if (m >= marker)
      ++m;
  m_preview.clear();
  m_flags.clear();
  const bool referenceChanged = referenceMarkerInserted(marker);
  storeReferenceMarkers();
  emit markersChanged();
  emit selectionChanged();
  if (referenceChanged)
    emit referenceMarkersChanged();
}

Take TakeDocument::exchangeTake(Take take)
{
  const std::vector<std::string> reference = referenceLabels();
  std::swap(m_take, take);
  const bool referenceChanged = mapReferenceLabels(reference);
  storeReferenceMarkers();
  m_hidden.assign(static_cast<std::size_t>(m_take.markerCount()), false);
  m_selection.clear();
  m_preview.clear();
  m_flags.clear();
  m_currentFrame = std::clamp<Eigen::Index>(m_currentFrame, 0, std::max<Eigen::Index>(m_take.frameCount() - 1, 0));
  emit markersChanged();
  emit selectionChanged();
  emit currentFrameChanged(m_currentFrame);
  if (referenceChanged)
    emit referenceMarkersChanged();
  return take;
}

bool TakeDocument::isHidden(Eigen::Index marker) const
{
  const auto index = static_cast<std::size_t>(marker);
  return marker >= 0 && index < m_hidden.size() && (m_hidden[index] || !isListed(marker));
}

bool TakeDocument::isListed(Eigen::Index point) const
{
  return point >= 0 && point < m_take.markerCount() && (m_showModelOutputs || isMarker(m_take, point));
}

std::vector<Eigen::Index> TakeDocument::listedPoints() const
{
  std::vector<Eigen::Index> points;
  for (Eigen::Index m = 0; m < m_take.markerCount(); ++m)
    if (isListed(m))
      points.push_back(m);
  return points;
}

void TakeDocument::setShowModelOutputs(bool show)
{
  if (show == m_showModelOutputs)
    return;
  m_showModelOutputs = show;
  emit visibilityChanged();
}

void TakeDocument::setHidden(const std::vector<Eigen::Index>& markers, bool hidden)
{
  bool changed = false;
  for (Eigen::Index m : markers) {
    const auto index = static_cast<std::size_t>(m);
    if (m >= 0 && index < m_hidden.size() && m_hidden[index] != hidden) {
      m_hidden[index] = hidden;
      changed = true;
    }
  }
  if (changed)
    emit visibilityChanged();
}

void TakeDocument::showAllMarkers()
{
  if (hiddenCount() == 0)
    return;
  std::fill(m_hidden.begin(), m_hidden.end(), false);
  emit visibilityChanged();
}

Eigen::Index TakeDocument::hiddenCount() const
{
  return static_cast<Eigen::Index>(std::count(m_hidden.begin(), m_hidden.end(), true));
}

} // namespace mocap::ui

namespace mocap::ui {

// Reference markers: one set per take, kept on the same labels through marker edits.

void TakeDocument::loadReferenceMarkers()
{
  m_removedReferenceLabels.clear();
  m_proposedReference.clear();
  const std::vector<std::string> saved = headMarkers(m_take);
  m_referenceSaved = !saved.empty();
  if (m_referenceSaved) {
    m_referenceMarkers.clear();
    for (const std::string& label : saved)
      if (const auto m = m_take.markerIndex(label))
        m_referenceMarkers.push_back(*m);
    std::sort(m_referenceMarkers.begin(), m_referenceMarkers.end());
    m_referenceMarkers.erase(std::unique(m_referenceMarkers.begin(), m_referenceMarkers.end()),
                             m_referenceMarkers.end());
    return;
  }
  m_referenceMarkers = labelledHeadMarkers(m_take);
  if (m_referenceMarkers.empty())
    m_proposedReference = headSizedRigidCluster(m_take);
}

void TakeDocument::storeReferenceMarkers()
{
  if (m_referenceSaved)
    setHeadMarkers(m_take, referenceLabels());
}

std::vector<std::string> TakeDocument::referenceLabels() const
{
  std::vector<std::string> labels;
  for (const Eigen::Index m : m_referenceMarkers)
    labels.push_back(m_take.label(m));
  return labels;
}

std::shared_ptr<const HeadMotion> TakeDocument::headMotion(const std::vector<Eigen::Index>& markers) const
{
  auto& cached = m_headMotions[markers];
  if (!cached) {
    try {
      cached = std::make_shared<const HeadMotion>(estimateHeadMotion(m_take, markers));
    } catch (...) {
      m_headMotions.erase(markers);  // no empty entry for a set that cannot carry a pose
      throw;
    }
  }
  return cached;
}

bool TakeDocument::isReferenceMarker(Eigen::Index marker) const
{
  return std::binary_search(m_referenceMarkers.begin(), m_referenceMarkers.end(), marker);
}

std::vector<Eigen::Index> TakeDocument::setReferenceMarkers(std::vector<Eigen::Index> markers, bool saved)
{
  markers.erase(std::remove_if(markers.begin(), markers.end(),
                               [this](Eigen::Index m) { return m < 0 || m >= m_take.markerCount(); }),
                markers.end());
  std::sort(markers.begin(), markers.end());
  markers.erase(std::unique(markers.begin(), markers.end()), markers.end());
  std::swap(markers, m_referenceMarkers);
  m_referenceSaved = saved;
  m_proposedReference.clear();  // the user has chosen: nothing left to propose
  setHeadMarkers(m_take, {});
  storeReferenceMarkers();
  if (markers != m_referenceMarkers)
    emit referenceMarkersChanged();
  return markers;
}

bool TakeDocument::referenceMarkerRemoved(Eigen::Index marker, const std::string& label)
{
  bool changed = false;
  std::vector<Eigen::Index> kept;
  for (const Eigen::Index m : m_referenceMarkers) {
    if (m == marker) {
      changed = true;
      m_removedReferenceLabels.push_back(label);
      continue;
    }
    kept.push_back(m > marker ? m - 1 : m);
    changed = changed || m > marker;
  }
  m_referenceMarkers = std::move(kept);
  return changed;
}

bool TakeDocument::referenceMarkerInserted(Eigen::Index marker)
{
  bool changed = false;
  for (Eigen::Index& m : m_referenceMarkers)
    if (m >= marker) {
      ++m;
      changed = true;
    }
  const auto removed =
      std::find(m_removedReferenceLabels.begin(), m_removedReferenceLabels.end(), m_take.label(marker));
  if (removed != m_removedReferenceLabels.end()) {
    m_removedReferenceLabels.erase(removed);
    m_referenceMarkers.insert(std::upper_bound(m_referenceMarkers.begin(), m_referenceMarkers.end(), marker), marker);
    changed = true;
  }
  return changed;
}

bool TakeDocument::mapReferenceLabels(const std::vector<std::string>& labels)
{
  // Labels the new take lacks are remembered, so exchanging back (undo) finds them again.
  std::vector<std::string> wanted = labels;
  wanted.insert(wanted.end(), m_removedReferenceLabels.begin(), m_removedReferenceLabels.end());
  m_removedReferenceLabels.clear();
  std::vector<Eigen::Index> markers;
  for (const std::string& label : wanted) {
    if (const auto m = m_take.markerIndex(label))
      markers.push_back(*m);
    else
      m_removedReferenceLabels.push_back(label);
  }
  std::sort(markers.begin(), markers.end());
  markers.erase(std::unique(markers.begin(), markers.end()), markers.end());
  const bool changed = markers != m_referenceMarkers;
  m_referenceMarkers = std::move(markers);
  return changed;
}

} // namespace mocap::ui
