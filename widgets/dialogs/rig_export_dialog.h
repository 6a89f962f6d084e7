#pragma once

#include "mocap/io/weight_output.h"
#include "mocap/math/key_reduction.h"
#include "mocap/model/blendshape_rig.h"
#include "mocap/model/retarget_map.h"

#include <QDialog>
#include <QString>

#include <Eigen/Core>

#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace mocap::ui {

class RetargetMapChooser;

/// What Export Rig writes from: the rig and its weight curves (copies), timed as the take is.
struct RigExportSource
{
  std::shared_ptr<const BlendshapeRig> rig;
  Eigen::MatrixXd weights;     ///< #frames × the rig's shapes
  double frameRate = 0.0;
  long long firstFrame = 0;    ///< the plain CSV's first frame number
  /// A recording's first timecode (seconds): the FBX's first key and time span, the glTF's
  /// extras.startSeconds, as `mocap convert REC.csv` writes them; none for a solve (from 0).
  std::optional<double> startSeconds;
  Eigen::MatrixXd headRotation;  ///< Live Link's head (× 3) or head and eyes (× 9) yaw, pitch, roll per frame, or empty (zeros)
  QString baseName;            ///< the output's default file name without extension (the take's)
  /// The Retarget section's map with its gains as edited there, offered (and chosen) as a map of
  /// its own; nullopt when the section has none.
  std::optional<RetargetMap> sectionMap;
  QString sectionMapName;      ///< what the section read it from (a shipped name or a path)
  bool sectionMapEdited = false;
};

/// writeWeightOutput's options for `source` as it is: its timing and head turn, no map, FBX Y up
/// in cm, every frame keyed. The dialog adds the user's choices to it.
[[nodiscard]] WeightOutput rigExportOptions(const RigExportSource& source);

/// What Export Rig writes: the rig with animated weights, or the curves alone.
enum class RigExportFormat
{
  Fbx,          ///< skinned mesh with blend-shape channels and DeformPercent curves (fbx_writer.h)
  Glb,          ///< glTF with morph targets and a weights animation (gltf_writer.h)
  WeightsCsv,   ///< Frame,Time,<shape>,… (weights_csv_writer.h)
  LiveLinkCsv,  ///< Live Link Face's own CSV (live_link_face_csv.h)
};

/// The Blendshape Solve dock's Export Rig dialog: the solved rig as FBX or glTF, or its curves as
/// CSV (plain or Live Link Face), through a retarget map (none, a shipped map, a map file, or the
/// Retarget section's map as edited there, chosen when the section has one) and,
/// for FBX and glTF, with keys reduced within a tolerance in weight units; FBX declares its up
/// axis and units. It writes through writeWeightOutput, as `mocap solve -o` and `mocap convert`
/// do, so the options mean what --map, --reduce, --up and --units mean there. The map is checked
/// against the rig as it is chosen; after writing, the status says the keys before and after and
/// the largest error. Every choice is remembered (session options "rigExport/…").
class RigExportDialog final : public QDialog
{
  Q_OBJECT

public:
  explicit RigExportDialog(RigExportSource source, QWidget* parent = nullptr);
  ~RigExportDialog() override;

  [[nodiscard]] RigExportFormat format() const;
  /// Selects `format` and gives the output path its extension.
  void setFormat(RigExportFormat format);
  [[nodiscard]] QString outputPath() const;
  void setOutputPath(const QString& path);

  /// The map as writeWeightOutput takes it: nullopt for none (or the section's map), a shipped
  /// map's name or a file.
  [[nodiscard]] std::optional<std::string> map() const;
  /// True when the Retarget section's map is chosen.
  [[nodiscard]] bool sectionMapChosen() const;
  /// Selects no map (""), a shipped map by name, or else a map file at `nameOrPath`.
  void setMap(const QString& nameOrPath);
  /// Selects the Retarget section's map (when the source has one).
  void chooseSectionMap();
  /// nullopt: every frame keyed; else the tolerance in weight units (FBX, glTF).
  [[nodiscard]] std::optional<double> reduction() const;
  void setReduction(std::optional<double> tolerance);
  void setUpAxis(FbxUpAxis up);
  void setUnits(LengthUnit unit);

  /// The options writeWeightOutput gets from the dialog's choices.
  [[nodiscard]] WeightOutput options() const;
  /// Checks the choices and writes the file (the Export button). Returns "" or the error, which
  /// the status shows; after writing it shows the keys before and after.
  QString exportNow();
  /// The keys the last export kept (FBX and glTF with a tolerance), else nullopt.
  [[nodiscard]] const std::optional<KeyCount>& lastKeys() const { return m_keys; }
  [[nodiscard]] QString statusText() const;

private:
  void buildLayout();
  QLayout* buildReductionRow();
  void restoreSettings();
  void writeSettings() const;
  void onFormatChanged();
  void onOptionsChanged();
  void browse();
  /// "" when the choices can be written, else why not (the map against the rig included).
  [[nodiscard]] QString checkSettings() const;
  [[nodiscard]] QString keysText(const std::optional<KeyCount>& keys) const;
  void showStatus(const QString& text, bool error);

  RigExportSource m_source;
  std::optional<KeyCount> m_keys;
  bool m_restoring = false;

  QComboBox* m_format = nullptr;
  QLineEdit* m_path = nullptr;
  QPushButton* m_browse = nullptr;
  RetargetMapChooser* m_map = nullptr;
  QCheckBox* m_reduce = nullptr;
  QDoubleSpinBox* m_tolerance = nullptr;
  QComboBox* m_up = nullptr;
  QComboBox* m_units = nullptr;
  QLabel* m_status = nullptr;
  QPushButton* m_export = nullptr;
};

} // namespace mocap::ui
