#pragma once

#include "document/retarget_map_model.h"

#include "mocap/deform/blendshape_solver.h"
#include "mocap/model/blendshape_rig.h"

#include <QObject>
#include <QString>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

namespace mocap::ui {

/// Weight curves read from a file rather than solved from the take (a Live Link Face recording):
/// where from, and the rate, first time and head turn they keep in exports (row i is shown at
/// take frame i).
struct ReadWeightCurves
{
  QString path;
  double frameRate = 0.0;     ///< of the curves: the take's when the recording was resampled to it
  double recordedRate = 0.0;  ///< the recording's own
  double startSeconds = 0.0;
  QString firstTimecode;  ///< as the file wrote it
  Eigen::MatrixXd headRotation;  ///< per row the recording's 9 rotations: head, left eye, right eye yaw/pitch/roll (radians)
};

/// The blendshape rig the open take is solved to and the weights solved, beside the document:
/// the rig (its neutral is the face mesh the binding is made on), the last solve's weights,
/// per-frame marker residual and held frames, the shapes selected for display and editing, and
/// the weight edits (through EditWeightsCommand on the document's undo stack). A new solve or rig
/// starts a new generation: edits made on an older one no longer apply. The solve itself runs
/// on a worker (BlendshapeSolvePanel); this model only holds its result.
class BlendshapeSolveModel final : public QObject
{
  Q_OBJECT

public:
  explicit BlendshapeSolveModel(QObject* parent = nullptr);
  ~BlendshapeSolveModel() override;

  /// Replaces the rig (`path` names it in the panel; `shapeFolder` holds an OBJ rig's shapes, so
  /// it can be read again); drops the weights.
  void setRig(std::shared_ptr<const BlendshapeRig> rig, QString path, QString shapeFolder = {});
  [[nodiscard]] const std::shared_ptr<const BlendshapeRig>& rig() const { return m_rig; }
  [[nodiscard]] bool hasRig() const { return m_rig != nullptr; }
  [[nodiscard]] const QString& rigPath() const { return m_rigPath; }
  [[nodiscard]] const QString& rigShapeFolder() const { return m_rigShapeFolder; }
  [[nodiscard]] QString shapeName(Eigen::Index shape) const;

  /// Takes a finished solve made with `options` (weights #frames × #shapes of
  /// the current rig; anything else is refused and returns false).
  bool setResult(BlendshapeSolveResult result, const BlendshapeSolveOptions& options);
  void clearResult();
  /// Swaps the curves (weights #frames × #shapes of the current rig) and where they were read
  /// from with the model's, without starting a new generation: ReplaceWeightCurvesCommand's
  /// undoable replacement, which keeps the edits around it on the stack in order.
  void swapCurves(BlendshapeSolveResult& curves, std::optional<ReadWeightCurves>& read);
  /// Where the curves were read from, or nullopt when they were solved (or there are none).
  [[nodiscard]] const std::optional<ReadWeightCurves>& readCurves() const { return m_read; }
  [[nodiscard]] bool hasResult() const { return m_result.weights.rows() > 0; }
  [[nodiscard]] const BlendshapeSolveResult& result() const { return m_result; }
  [[nodiscard]] const Eigen::MatrixXd& weights() const { return m_result.weights; }
  [[nodiscard]] const BlendshapeSolveOptions& solvedWith() const { return m_options; }
  /// Counts rig and result replacements (EditWeightsCommand checks it).
  [[nodiscard]] int generation() const { return m_generation; }

  /// Replaces rows first … first + values.rows() − 1 of the weight columns `shapes` (values has one
  /// column per entry of `shapes`, clamped to [0, 1]) and returns what they were, so applying
  /// the result undoes the change. Throws InvalidArgument for a block outside the weights.
  /// O(block size).
  Eigen::MatrixXd replaceWeights(const std::vector<Eigen::Index>& shapes, Eigen::Index first,
                                 const Eigen::Ref<const Eigen::MatrixXd>& values);
  /// The weights of `shapes` over frames first … last (#frames × #shapes). O(block size).
  [[nodiscard]] Eigen::MatrixXd weightBlock(const std::vector<Eigen::Index>& shapes, Eigen::Index first,
                                            Eigen::Index last) const;

  /// The actor profile the solve uses (its neutral and range, `mocap solve --actor`), or none;
  /// `path` is the file it was read from. ActorActions loads it and remembers it with the take.
  void setActor(std::shared_ptr<const ActorProfile> actor, QString path);
  [[nodiscard]] const std::shared_ptr<const ActorProfile>& actor() const { return m_actor; }
  [[nodiscard]] const QString& actorPath() const { return m_actorPath; }

  /// The map the Retarget section shows the curves through (kept when the rig or take changes).
  [[nodiscard]] RetargetMapModel& retargetMap() { return m_retargetMap; }
  [[nodiscard]] const RetargetMapModel& retargetMap() const { return m_retargetMap; }

  /// The shapes shown as curves and edited, ascending.
  void setSelectedShapes(std::vector<Eigen::Index> shapes);
  [[nodiscard]] const std::vector<Eigen::Index>& selectedShapes() const { return m_selected; }

  /// The rig posed at `frame` (neutral + Σ w·Δ) into `out`; false without a result for it.
  /// O(#vertices + Σ #moved vertices).
  bool pose(Eigen::Index frame, MeshVertices& out) const;

signals:
  void rigChanged();
  /// A new solve or none (cleared).
  void resultChanged();
  /// Weight edits changed frames first … last.
  void weightsEdited(Eigen::Index first, Eigen::Index last);
  void selectedShapesChanged();
  void actorChanged();

private:
  std::shared_ptr<const BlendshapeRig> m_rig;
  QString m_rigPath;
  QString m_rigShapeFolder;
  BlendshapeSolveResult m_result;
  BlendshapeSolveOptions m_options;
  std::optional<ReadWeightCurves> m_read;
  int m_generation = 0;
  std::vector<Eigen::Index> m_selected;
  RetargetMapModel m_retargetMap;
  std::shared_ptr<const ActorProfile> m_actor;
  QString m_actorPath;
};

} // namespace mocap::ui
