#pragma once

#include "dialogs/animation_export_job.h"

#include <QDialog>

#include <optional>


class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace mocap::ui {

class JobRunner;
class TakeDocument;

/// File ▸ Export Animation: the markers as BVH or FBX (animated nulls, the up axis declared, keys
/// optionally reduced within a tolerance in mm as `mocap convert --reduce`; the keys kept and the
/// largest error are reported), or the deformed face mesh as an OBJ sequence or an
/// OBJ + PC2 point cache, over a frame range: the whole take unless the user picks the range
/// selected on the curves or types one. Existing files are replaced only after the user agreed
/// (a question listing them). The export runs on a worker thread with a progress bar and Cancel;
/// a cancelled or failed export leaves no file. The last folder, format and FBX options are
/// remembered (session options "export/folder", "export/format", "export/fbx…"). The mesh formats need a source of
/// deformed frames (setMeshSource); without one they are disabled.
class ExportDialog final : public QDialog
{
  Q_OBJECT

public:
  explicit ExportDialog(const TakeDocument& document, QWidget* parent = nullptr);
  /// Cancels a running export and waits for it to stop.
  ~ExportDialog() override;

  /// The deformed mesh for the mesh formats: `mesh` and its vertices per take frame, which
  /// `source` computes on the worker thread. `name` is the stem of the sequence files.
  void setMeshSource(Mesh mesh, MeshFrameSource source, const QString& name);

  [[nodiscard]] AnimationFormat format() const;
  /// Selects `format` (ignored while it is disabled) and gives the output path its extension.
  void setFormat(AnimationFormat format);
  [[nodiscard]] QString outputPath() const;
  void setOutputPath(const QString& path);
  /// Frame numbers as the take counts them (from Take::firstFrame()), both included.
  void setFrameRange(qint64 first, qint64 last);
  /// FBX: the up axis declared, and the key tolerance in mm (nullopt: every frame a key).
  void setFbxOptions(FbxUpAxis up, std::optional<double> reduceMm);
  /// BVH, FBX: the units the markers are written in (nullopt: the take's own).
  void setMarkerUnits(std::optional<LengthUnit> units);
  [[nodiscard]] qint64 firstFrame() const;
  [[nodiscard]] qint64 lastFrame() const;
  /// What the Range box offers: the whole take (the default), the range selected on the curves
  /// (only when there is one), or the frames typed in.
  enum class RangeChoice
  {
    WholeTake,
    SelectedRange,
    Custom,
  };
  [[nodiscard]] RangeChoice rangeChoice() const;
  void setRangeChoice(RangeChoice choice);

  /// Checks the settings and starts the export on a worker thread (the Export button). Returns
  /// false, with the reason in the dialog, when they cannot be used.
  bool startExport();
  /// Asks a running export to stop; it removes what it wrote (the Cancel button while running).
  void cancelExport();
  [[nodiscard]] bool isRunning() const;
  /// The export's background job (its finished() is what a test waits on).
  [[nodiscard]] const JobRunner& jobs() const { return *m_jobs; }
  /// The last message shown under the progress bar (an error, "cancelled", or what was written).
  [[nodiscard]] QString statusText() const;

  /// Escape, Cancel and the close button stop a running export instead of closing the dialog.
  void reject() override;

signals:
  /// An export ended: `succeeded` is false when it failed or was cancelled.
  void exportFinished(bool succeeded);

private:
  void buildLayout();
  QLayout* buildFbxRow();
  void fillUnits(LengthUnit takeUnits);
  void restoreSettings();
  void browse();
  void onFormatChanged();
  void onFinished(const ExportOutcome& outcome);
  void showProgress(double fraction, const QString& timeLeft);
  void setRunning(bool running);
  void onRangeChoiceChanged();
  void onFramesEdited();
  /// True when the user agreed to replace what `job` would overwrite (or nothing would be).
  [[nodiscard]] bool confirmReplacing(const AnimationExportJob& job);
  void showStatus(const QString& text, bool error);
  [[nodiscard]] QString keysText(const KeyCount& keys) const;
  [[nodiscard]] QString checkSettings() const;
  [[nodiscard]] AnimationExportJob makeJob() const;

  const TakeDocument& m_document;
  Mesh m_mesh;
  MeshFrameSource m_source;
  QString m_meshName;
  AnimationFormat m_rememberedFormat = AnimationFormat::Bvh;

  QComboBox* m_format = nullptr;
  QLineEdit* m_path = nullptr;
  QPushButton* m_browse = nullptr;
  QComboBox* m_up = nullptr;
  QComboBox* m_units = nullptr;  ///< the markers' units in the file: the take's own (-1), or mm, cm, m
  QCheckBox* m_reduce = nullptr;
  QDoubleSpinBox* m_reduceMm = nullptr;
  QComboBox* m_range = nullptr;
  QSpinBox* m_first = nullptr;
  QSpinBox* m_last = nullptr;
  QProgressBar* m_progressBar = nullptr;
  QLabel* m_status = nullptr;
  QPushButton* m_export = nullptr;
  QPushButton* m_cancel = nullptr;
  JobRunner* m_jobs = nullptr;
  long long m_total = 0;
  QString m_runningText;  // "Exporting 1200 frames…", followed by the time left
  QString m_runningOutput;
};

} // namespace mocap::ui
