#pragma once

#include "mocap/model/sample_patch.h"
#include "mocap/model/take.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QUndoStack>

#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace mocap {
struct HeadMotion; // mocap/cleaning/head_stabilization.h
}

namespace mocap::ui {

/// The open take and everything the views share about it: file path, undo stack, current
/// frame and marker selection. Only commands change the take's samples; they call
/// applyPatches() here, which emits samplesChanged so every view redraws from the document.
class TakeDocument final : public QObject
{
  Q_OBJECT

public:
  explicit TakeDocument(QObject* parent = nullptr);

  [[nodiscard]] const Take& take() const { return m_take; }
  [[nodiscard]] const QString& filePath() const { return m_filePath; }
  [[nodiscard]] bool hasTake() const { return !m_take.empty(); }
  [[nodiscard]] QUndoStack* undoStack() { return &m_undoStack; }
  [[nodiscard]] bool isModified() const { return !m_undoStack.isClean(); }
  /// The file the open take was read from, whose warnings loadWarnings() are: Save As changes
  /// filePath(), not this (the list said "while reading" the saved copy, which reads without them).
  [[nodiscard]] const QString& readFilePath() const { return m_readFilePath; }
  /// Warnings from the last successful open (tolerated file quirks), all of them.
  [[nodiscard]] const std::vector<std::string>& loadWarnings() const { return m_loadWarnings; }
  /// The warnings of the last open that mean data is missing (truncation) or wrong (wrapped
  /// coordinates, a misread layout), with those a saved copy's history carried and nobody
  /// acknowledged ("recorded when FILE was read: …").
  [[nodiscard]] const std::vector<std::string>& dataLossWarnings() const { return m_dataLoss; }
  /// True when the open take lost data at open: the title says what kind (dataLossKinds).
  [[nodiscard]] bool hasDataLoss() const { return !m_dataLoss.empty(); }

  /// A take as read from a file, with the reader's warnings, before it becomes the document's.
  struct ReadResult
  {
    Take take;
    std::vector<std::string> warnings, dataLoss;
  };
  /// Reads `path`; throws what the readers throw. Touches no document, so it may run on a
  /// worker thread (the studio opens large files so).
  [[nodiscard]] static ReadResult read(const QString& path);
  /// Makes `read` (of `path`) the document's take, as open does.
  void open(ReadResult read, const QString& path);
  /// Reads `path` into a fresh take and replaces the current one only when the read succeeds.
  /// Returns an empty string on success, else the error message (the open take is untouched).
  QString open(const QString& path);
  /// Writes the take atomically (format by extension). Returns an empty string or the error.
  /// `markClean` makes the written file the document's file (Save / Save As, not Export).
  QString save(const QString& path, bool markClean = true);
  /// Marks the take as having unsaved edits that are not in the undo history (a recovered
  /// take), so closing asks to save it.
  void markModified() { m_undoStack.resetClean(); }
  /// Replaces the take (e.g. a new take built in code); clears the undo history.
  void setTake(Take take, const QString& path = {});

  [[nodiscard]] Eigen::Index currentFrame() const { return m_currentFrame; }
  void setCurrentFrame(Eigen::Index frame);
  [[nodiscard]] const std::vector<Eigen::Index>& selection() const { return m_selection; }
  void setSelection(std::vector<Eigen::Index> markers);
  /// Selects the markers with these labels (trimmed; a label the take lacks is left out) and
  /// returns how many were found: the command lines' --select. O(#labels · #markers).
  int selectLabels(const QStringList& labels);

  /// Puts `patches` into the take and returns the undo patches (for commands only).
  std::vector<SamplePatch> applyPatches(std::vector<SamplePatch> patches);
  /// Takes a marker out of the take and returns it (for commands only). Selection and hidden
  /// markers follow the index shift; emits markersChanged.
  MarkerColumn removeMarker(Eigen::Index marker);
  /// Puts a marker in at `marker` (for commands only); throws InvalidArgument as
  /// Take::insertMarker does, leaving everything unchanged. Emits markersChanged.
  void insertMarker(Eigen::Index marker, MarkerColumn column);

  /// Exchanges the whole take for `take` and returns the old one (for commands that rebuild the
  /// take, e.g. tracking and labelling). Selection, hidden markers, preview and flags are reset;
  /// the undo history and file stay. Emits markersChanged.
  Take exchangeTake(Take take);

  /// Hidden markers are not drawn in the 3D and curve views (a view setting, not an edit): the
  /// ones the user hid, and model outputs while they are not listed (isListed).
  [[nodiscard]] bool isHidden(Eigen::Index marker) const;
  void setHidden(const std::vector<Eigen::Index>& markers, bool hidden);
  void showAllMarkers();
  /// The markers the user hid (model outputs left out by isListed do not count).
  [[nodiscard]] Eigen::Index hiddenCount() const;

  /// Whether point `point` is drawn and listed (3D view, gap list, timeline gap marks): every
  /// marker point, and model outputs (marker_points.h: angles, forces...) only while
  /// showsModelOutputs() is on. O(1).
  [[nodiscard]] bool isListed(Eigen::Index point) const;
  /// The listed points, ascending. O(#points).
  [[nodiscard]] std::vector<Eigen::Index> listedPoints() const;
  /// View ▸ Show Model Outputs (off by default; the studio remembers it). A view setting, not an
  /// edit; emits visibilityChanged when it changes.
  [[nodiscard]] bool showsModelOutputs() const { return m_showModelOutputs; }
  void setShowModelOutputs(bool show);

  /// Appends a step to the take's processing history (for commands only); emits historyChanged.
  void appendHistory(ProcessingStep step);
  /// Removes the newest history step and returns it (for commands only; the undo of
  /// appendHistory). Emits historyChanged.
  ProcessingStep removeLastHistory();

  /// Renames a marker and returns the old label (for commands only). Throws
  /// InvalidArgument for an empty or duplicate label.
  std::string renameMarker(Eigen::Index marker, std::string label);

  /// Patches a cleaning panel proposes, drawn over the take but not in it (live preview).
  [[nodiscard]] const std::vector<SamplePatch>& preview() const { return m_preview; }
  void setPreview(std::vector<SamplePatch> patches);
  void clearPreview() { setPreview({}); }
  /// Samples to point out for review (e.g. detected spikes): (marker, frame) pairs.
  [[nodiscard]] const std::vector<std::pair<Eigen::Index, Eigen::Index>>& flags() const { return m_flags; }
  void setFlags(std::vector<std::pair<Eigen::Index, Eigen::Index>> flags);

  /// The head-mounted reference markers of the take (indices, ascending): the one set that head
  /// stabilization, the head-stabilized view, layout planning and the face mesh use. When a take
  /// is set: the set saved with it (headMarkers in provenance.h), else its root*/head* labelled markers
  /// (labelledHeadMarkers), else none, with the most rigid cluster proposed
  /// (proposedReferenceMarkers) for the user to accept, never taken silently. A set chosen by
  /// setReferenceMarkers is saved with the take; removing, inserting or exchanging markers keeps
  /// it on the same labels.
  [[nodiscard]] const std::vector<Eigen::Index>& referenceMarkers() const { return m_referenceMarkers; }
  /// The reference markers' labels, in marker order.
  [[nodiscard]] std::vector<std::string> referenceLabels() const;
  /// The take's head motion estimated from `markers` (mocap::estimateHeadMotion), computed once
  /// per state of the take and shared by everything that draws in the head frame (the 3D view, the
  /// face mesh and its placement): the cache is dropped on a new take and on every edit of samples
  /// or markers. Throws as estimateHeadMotion. O(#frames · #markers) when not cached.
  [[nodiscard]] std::shared_ptr<const HeadMotion> headMotion(const std::vector<Eigen::Index>& markers) const;
  [[nodiscard]] bool isReferenceMarker(Eigen::Index marker) const;
  /// Replaces the set (for SetReferenceMarkersCommand only; out-of-range indices are dropped)
  /// and returns the old one. `saved`: the set becomes the take's own, its labels stored in the
  /// take (setHeadMarkers, which saving and autosave write); else the take's are cleared.
  /// Emits referenceMarkersChanged when it changed.
  std::vector<Eigen::Index> setReferenceMarkers(std::vector<Eigen::Index> markers, bool saved = true);
  /// Whether the set is the take's own (saved with it, chosen or accepted), not only named by labels.
  [[nodiscard]] bool referenceMarkersSaved() const { return m_referenceSaved; }
  /// The reference markers proposed for a take that has none saved and no root*/head* labels
  /// (mostRigidCluster), for the user to accept or replace; empty otherwise. Not used by anything
  /// until accepted through setReferenceMarkers.
  [[nodiscard]] const std::vector<Eigen::Index>& proposedReferenceMarkers() const { return m_proposedReference; }

  /// The frame range selected on the curves, [first, last]; empty when first > last.
  [[nodiscard]] Eigen::Index rangeFirst() const { return m_rangeFirst; }
  [[nodiscard]] Eigen::Index rangeLast() const { return m_rangeLast; }
  [[nodiscard]] bool hasRange() const { return m_rangeFirst <= m_rangeLast; }
  void setRange(Eigen::Index first, Eigen::Index last);
  void clearRange() { setRange(0, -1); }

signals:
  /// A different take was loaded (or the take was replaced): views rebuild everything.
  void takeReset();
  /// Samples of these markers changed (an edit, its undo or redo).
  void samplesChanged(const std::vector<Eigen::Index>& markers);
  void currentFrameChanged(Eigen::Index frame);
  void selectionChanged();
  void modifiedChanged(bool modified);
  void filePathChanged(const QString& path);
  void markerRenamed(Eigen::Index marker);
  /// Markers were removed or inserted (indices shifted): views rebuild their per-marker state.
  void markersChanged();
  void visibilityChanged();
  void rangeChanged();
  void previewChanged();
  void flagsChanged();
  /// The take's processing history changed (a step applied or undone, a take opened).
  void historyChanged();
  /// The reference markers changed: an edit of the set, a marker of it removed, inserted or renamed,
  /// or indices shifted (emitted after markersChanged).
  void referenceMarkersChanged();

private:
  Take m_take;
  QString m_filePath;
  QUndoStack m_undoStack;
  Eigen::Index m_currentFrame = 0;
  std::vector<Eigen::Index> m_selection;
  QString m_readFilePath;
  std::vector<std::string> m_loadWarnings;
  std::vector<std::string> m_dataLoss;
  std::vector<bool> m_hidden;  // one per marker
  bool m_showModelOutputs = false;
  std::vector<SamplePatch> m_preview;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> m_flags;
  Eigen::Index m_rangeFirst = 0;
  Eigen::Index m_rangeLast = -1;

  // Reference markers (see referenceMarkers()).
  void loadReferenceMarkers();
  /// Writes the set's labels into the take when the set is the take's own (saved or chosen).
  void storeReferenceMarkers();
  // Each returns whether the set changed; the caller emits referenceMarkersChanged after markersChanged.
  bool referenceMarkerRemoved(Eigen::Index marker, const std::string& label);
  bool referenceMarkerInserted(Eigen::Index marker);
  bool mapReferenceLabels(const std::vector<std::string>& labels);
  std::vector<Eigen::Index> m_referenceMarkers;
  std::vector<Eigen::Index> m_proposedReference;
  bool m_referenceSaved = false;  // the set is the take's own: saved with it, chosen, or accepted
  mutable std::map<std::vector<Eigen::Index>, std::shared_ptr<const HeadMotion>> m_headMotions;
  /// Labels of reference markers removed from the take: a marker inserted with one of them (the
  /// undo of the removal) rejoins the set.
  std::vector<std::string> m_removedReferenceLabels;
};

} // namespace mocap::ui
