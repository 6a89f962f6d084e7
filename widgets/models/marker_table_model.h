#pragma once

#include <QAbstractTableModel>

#include <Eigen/Core>

#include <vector>

namespace mocap::ui {

class TakeDocument;

/// One row per marker: label, % valid, gap count, longest gap, bad points flagged for review. Sort through a
/// QSortFilterProxyModel (Qt::UserRole gives the raw number of each cell). Statistics are
/// recomputed only for the markers a change touches.
class MarkerTableModel final : public QAbstractTableModel
{
  Q_OBJECT

public:
  enum Column
  {
    LabelColumn,
    ValidColumn,
    GapsColumn,
    LongestGapColumn,
    BadPointsColumn,
    ColumnCount
  };

  explicit MarkerTableModel(TakeDocument& document, QObject* parent = nullptr);

  [[nodiscard]] int rowCount(const QModelIndex& parent = {}) const override;
  [[nodiscard]] int columnCount(const QModelIndex& parent = {}) const override;
  [[nodiscard]] QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
  [[nodiscard]] Qt::ItemFlags flags(const QModelIndex& index) const override;
  /// Editing a label pushes a RenameMarkerCommand (the model never changes the take itself);
  /// an empty or duplicate label is refused.
  bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

private:
  struct MarkerStats
  {
    double validPercent = 0.0;
    int gaps = 0;
    Eigen::Index longestGap = 0;
  };
  void rebuild();
  void refresh(const std::vector<Eigen::Index>& markers);
  void countFlags();
  [[nodiscard]] MarkerStats statsOf(Eigen::Index marker) const;

  TakeDocument& m_document;
  std::vector<MarkerStats> m_stats;
  std::vector<int> m_badPoints;  // flags per marker
};

} // namespace mocap::ui
