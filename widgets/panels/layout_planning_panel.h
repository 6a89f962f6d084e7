#pragma once

#include "mocap/layout/layout_planning.h"

#include <QString>
#include <QStringList>
#include <QWidget>

#include <memory>
#include <string>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace mocap::ui {

class JobRunner;
class LayoutErrorPlot;
class LayoutPlanModel;
struct LayoutPlanResult;
class ReferenceMarkersRow;
class StudioSession;
class TakeDocument;

/// What the layout planning panel runs with (remembered as session options, "layoutPlanning/…").
struct LayoutPlanParameters
{
  QStringList extraTakes;  ///< take files planned together with the open take
  SelectionMethod method = SelectionMethod::Pfa;
  double variance = 0.98;  ///< PCA variance kept
  int restarts = 1000;     ///< k-means restarts per k
  int minK = 0;            ///< 0 with maxK 0: every useful k
  int maxK = 0;
  int seed = 1;
  int randomSubsets = 20;  ///< random marker sets per size for the baseline (0: none)
  QString keyPoses;        ///< empty or "auto": automatic; else frame numbers (TAKE:FRAME for a further take)
  QString pairsFile;       ///< empty: pairs detected automatically
  QStringList markerPatterns;   ///< globs of the markers to plan; empty: every marker but unlabelled
                                ///< points and the take's reference markers
  QStringList excludePatterns;  ///< globs of markers left out of the plan
};

/// The core request (layout_planning.h) the parameters and the take's reference markers make, as
/// `mocap pfa` makes it from its options. Throws LayoutRequestError for malformed key poses.
[[nodiscard]] LayoutRequest layoutRequest(const LayoutPlanParameters& parameters,
                                          const std::vector<std::string>& referenceLabels);

/// The marker layout planning dock (Wellein et al. 2007 via layout_planning.h, the planning `mocap pfa`
/// runs): the open take plus optional take files, method and parameters; Run plans on a worker
/// thread with progress and Cancel; the result goes to the session's layout plan (LayoutPlanModel,
/// whose picked layout the 3D view highlights); the error-vs-marker-count plot picks a size; the
/// picked size's markers with their pair frequencies; export of the reduced label list, marker-set
/// file and take. Head motion is removed with the take's reference markers
/// (TakeDocument::referenceMarkers), which are not planned over, as `mocap pfa --stabilize` does.
/// Planning reads a copy of the take, so editing meanwhile is safe.
class LayoutPlanningPanel final : public QWidget
{
  Q_OBJECT

public:
  /// Plans the session's take, judges on its bound rig when asked, and keeps the result in its
  /// layout plan.
  explicit LayoutPlanningPanel(StudioSession& session, QWidget* parent = nullptr);
  ~LayoutPlanningPanel() override;

  [[nodiscard]] LayoutPlanParameters parameters() const;
  /// Judge layouts on the rig too (as `mocap pfa --rig`); remembered.
  void setJudgeOnRig(bool on);
  void setParameters(const LayoutPlanParameters& parameters);

  /// Starts a run with the current parameters; returns an error message (shown too) when it
  /// cannot start, else an empty string.
  QString run();
  /// Asks a running plan to stop; the panel goes idle when the worker returns what it has.
  void cancel();
  [[nodiscard]] bool busy() const;
  /// The panel's background job (its finished() is what a test waits on).
  [[nodiscard]] const JobRunner& jobs() const { return *m_jobs; }

  [[nodiscard]] LayoutErrorPlot* plot() const { return m_plot; }
  [[nodiscard]] QString statusText() const;

  /// Exports of the selected layout; each returns an error message or an empty string and writes
  /// atomically. The take and marker set also hold the head reference markers, which a capture
  /// with the reduced layout still needs; the label list holds the planned markers only.
  QString exportLabelList(const QString& path) const;
  QString exportMarkerSet(const QString& path) const;
  QString exportTake(const QString& path) const;

signals:
  /// The user asked to edit the reference markers (the main window opens the one editor).
  void editReferenceMarkersRequested();

private:
  void buildForm();
  void readSettings();
  void writeSettings() const;
  void onFinished(std::shared_ptr<LayoutPlanResult> result);
  /// Shows a plan in the plot and the status line (nullptr: none).
  void showResult(std::shared_ptr<const LayoutPlanResult> result);
  /// Follows the session's plan: shows one made elsewhere, its picked size and the size's markers.
  void followPlan();
  void showSelectedSize();
  void setIdle(bool idle);
  void showError(const QString& message);
  void exportWithDialog(const QString& title, const QString& filter,
                        QString (LayoutPlanningPanel::*write)(const QString&) const);
  /// Builds the request into `request` and checks it against the open take: an error message, or
  /// an empty string.
  QString checkedRequest(const LayoutPlanParameters& parameters, const std::vector<std::string>& reference,
                         LayoutRequest& request) const;

  StudioSession& m_session;
  TakeDocument& m_document;
  LayoutPlanModel& m_plan;
  QCheckBox* m_judgeOnRig = nullptr;
  QLabel* m_rigSummary = nullptr;
  QListWidget* m_takes = nullptr;
  QPushButton* m_addTake = nullptr;
  QPushButton* m_removeTake = nullptr;
  QComboBox* m_method = nullptr;
  QDoubleSpinBox* m_variance = nullptr;
  QSpinBox* m_restarts = nullptr;
  QSpinBox* m_minK = nullptr;
  QSpinBox* m_maxK = nullptr;
  QSpinBox* m_seed = nullptr;
  QLineEdit* m_pairs = nullptr;
  ReferenceMarkersRow* m_reference = nullptr;
  QLineEdit* m_markerPatterns = nullptr;
  QLineEdit* m_exclude = nullptr;
  QLineEdit* m_keyPoses = nullptr;
  QSpinBox* m_randomSubsets = nullptr;
  QPushButton* m_run = nullptr;
  JobRunner* m_jobs = nullptr;
  QLabel* m_status = nullptr;
  LayoutErrorPlot* m_plot = nullptr;
  std::shared_ptr<const LayoutPlanResult> m_shown;  // the plan in the plot and status line
  QTableWidget* m_markers = nullptr;
  QPushButton* m_exportLabels = nullptr;
  QPushButton* m_exportSet = nullptr;
  QPushButton* m_exportTake = nullptr;

  bool m_idle = true;  // false from Run until the result is shown
};

} // namespace mocap::ui
