#pragma once

#include "document/bound_rig.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>

class QUndoStack;

namespace mocap::ui {

class BlendshapeSolveModel;
class FaceMeshModel;
class LayoutPlanModel;
class LiveStream;
class ReferenceVideos;
struct SessionState;
struct StudioOptions;
class TakeDocument;
class ViewState;

/// The studio's composition root for the open take: it owns the TakeDocument (the take, its
/// undo stack, frame, selection and reference markers), the FaceMeshModel (mesh, binding, rigs)
/// and the BlendshapeSolveModel (blendshape rig, solved weights), which share the document's one
/// undo stack, the take's ReferenceVideos (with their sidecar) and the LayoutPlanModel (the last
/// marker layout plan and its picked size), and keeps the face mesh on the take's reference markers (head motion removed with
/// them). Panels and views are given the session (or its models) and observe them; no panel owns
/// a model or knows another panel.
///
/// Context belongs to one take: when the document gets a new take (opened, recovered), the
/// previous take's face mesh, binding, blendshape rig and weights are dropped, so nothing of
/// another take is drawn on this one. With keepRig() on (an actor's rig reused across takes),
/// the mesh, its binding and the blendshape rig are kept instead and the binding is re-bound to
/// the new take's labels (FaceMeshModel::bindKeptRig); solved weights never carry over.
class StudioSession final : public QObject
{
  Q_OBJECT

public:
  explicit StudioSession(QObject* parent = nullptr);
  ~StudioSession() override;
  StudioSession(const StudioSession&) = delete;
  StudioSession& operator=(const StudioSession&) = delete;

  [[nodiscard]] TakeDocument& document() const { return *m_document; }
  [[nodiscard]] FaceMeshModel& faceMesh() const { return *m_faceMesh; }
  [[nodiscard]] BlendshapeSolveModel& blendshapes() const { return *m_blendshapes; }
  [[nodiscard]] ReferenceVideos& referenceVideos() const { return *m_videos; }
  [[nodiscard]] LayoutPlanModel& layoutPlan() const { return *m_layoutPlan; }
  /// The live stream of the take's current frame to engines (View ▸ Live Stream).
  [[nodiscard]] LiveStream& liveStream() const { return *m_liveStream; }
  /// How the session is shown (up axis, trails, unit, colours, highlight…): the views observe it.
  [[nodiscard]] ViewState& view() const { return *m_view; }
  /// The user's remembered settings (read from QSettings when the session is made).
  [[nodiscard]] StudioOptions& options() const { return *m_options; }
  /// From now on the session follows the options: the view state, keepRig() and whether the
  /// document shows model outputs (the studio calls it; a session for a review video does not).
  void followOptions();
  /// The one undo stack (the document's): take edits, binding edits and weight edits undo in order.
  [[nodiscard]] QUndoStack* undoStack() const;

  /// Keep the face mesh, binding and blendshape rig when another take is opened (off: a new
  /// take starts without them).
  void setKeepRig(bool keep) { m_keepRig = keep; }
  [[nodiscard]] bool keepRig() const { return m_keepRig; }

  /// Makes `rig` (read from `path`, with an OBJ rig's `shapeFolder`) the blendshape rig; its
  /// neutral becomes the face mesh, since the binding is made on it (a face mesh of the same
  /// vertex count, e.g. the OBJ it came from, is kept with its binding).
  void setBlendshapeRig(std::shared_ptr<const BlendshapeRig> rig, const QString& path, const QString& shapeFolder = {});

  /// Everything the session holds beside its take, as a value (session_state.h): what crash
  /// recovery writes beside the take. Copies only (the weights, the binding); O(#frames · #shapes).
  [[nodiscard]] SessionState saveState() const;
  /// Brings saveState()'s state back onto the take set now: the face mesh and rig read from their
  /// files again, the binding, the weight curves with their edits and solve settings, the selected
  /// shapes, the reference videos with their offsets, the layout plan with its picked size, the
  /// actor profile and the Retarget section's map with its edited gains.
  /// What cannot be restored (a file gone, curves for another take's length) is left out and said:
  /// returns "" or the problems, one a line. Not undoable (the take's history is not either).
  QString restoreState(const SessionState& state);

  /// The blendshape rig with the binding made on its neutral (the face mesh is the rig's
  /// neutral); empty otherwise.
  [[nodiscard]] BoundRig boundRig() const;

signals:
  /// A new take's context is set up: emptied, or with the kept rig re-bound (`rigKept`).
  void takeContextReset(bool rigKept);

private:
  struct KeptRig;
  /// First on a new take: the previous take's context goes (kept aside when keepRig()).
  void dropPreviousTake();
  void followReferenceMarkers();
  /// restoreState's weight curves and reference videos.
  void restoreCurves(const SessionState& state, QStringList& problems);
  void restoreVideos(const SessionState& state, QStringList& problems);
  void restoreActorAndMap(const SessionState& state, QStringList& problems);
  /// Last on a new take, once the models have it: the kept rig bound to its labels.
  void restoreKeptRig();

  TakeDocument* m_document = nullptr;
  FaceMeshModel* m_faceMesh = nullptr;
  BlendshapeSolveModel* m_blendshapes = nullptr;
  ReferenceVideos* m_videos = nullptr;
  LayoutPlanModel* m_layoutPlan = nullptr;
  LiveStream* m_liveStream = nullptr;
  ViewState* m_view = nullptr;
  std::unique_ptr<StudioOptions> m_options;
  bool m_keepRig = false;
  std::unique_ptr<KeptRig> m_kept;  // between dropPreviousTake and restoreKeptRig
};

} // namespace mocap::ui
