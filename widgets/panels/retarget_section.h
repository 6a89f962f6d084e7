#pragma once

#include "mocap/model/retarget_map.h"

#include <QGroupBox>
#include <QString>

#include <optional>
#include <string>
#include <utility>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace mocap::ui {

class BlendshapeSolveModel;
class MappedCurvePlot;
class RetargetMapChooser;
class RetargetMapModel;
class TakeDocument;

/// The solve dock's Retarget section: load a retarget map (a shipped map or a file, as --map takes
/// it), its channels and sources in a table whose gains are edited in place (each edit one undoable
/// step, EditRetargetGainCommand), each channel's peak over the solved curves, and the selected
/// row's mapped curve over its source's weight (MappedCurvePlot). A map that does not fit the rig
/// (a source it lacks) says so by its line. Save Map As… writes the edited map as JSON, for Export
/// Rig and `mocap solve --map`. Mapping is O(#frames · Σ #sources) on each change.
class RetargetSection final : public QGroupBox
{
  Q_OBJECT

public:
  RetargetSection(TakeDocument& document, BlendshapeSolveModel& solve, RetargetMapModel& map,
                  QWidget* parent = nullptr);

  /// Loads a shipped map or a map file, or none (nullopt). Returns "" or the error shown.
  QString loadMap(const std::optional<std::string>& nameOrPath);
  /// Writes the map (with its edited gains) to `path`. Returns "" or the error shown.
  QString saveMap(const QString& path);
  /// Sets the gain of table row `row` as an undoable edit. Returns "" or why not.
  QString setGain(int row, double gain);
  /// Shows the mapped curve of table row `row`.
  void selectRow(int row);

  [[nodiscard]] QTableWidget* table() const { return m_table; }
  [[nodiscard]] MappedCurvePlot* plot() const { return m_plot; }
  /// The map's channels over the current curves, or nullopt (no map, no curves, a map that does not fit).
  [[nodiscard]] const std::optional<MappedWeights>& mapped() const { return m_mapped; }
  [[nodiscard]] QString statusText() const;

private:
  void fillTable();
  void showMapChoice();
  void updateMapped();
  void onItemChanged(int row, int column);
  void onGainChanged(int channel, int source);
  void showSelectedCurve();
  void saveDialog();
  void showStatus(const QString& text, bool error);

  TakeDocument& m_document;
  BlendshapeSolveModel& m_solve;
  RetargetMapModel& m_map;
  std::vector<std::pair<int, int>> m_rows;  // (channel, source) per table row; source −1: none
  std::optional<MappedWeights> m_mapped;
  bool m_filling = false;

  RetargetMapChooser* m_chooser = nullptr;
  QPushButton* m_save = nullptr;
  QTableWidget* m_table = nullptr;
  MappedCurvePlot* m_plot = nullptr;
  QLabel* m_status = nullptr;
};

} // namespace mocap::ui
