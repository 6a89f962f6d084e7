#pragma once

#include "mocap/evaluation/layout_rig_error.h"
#include "mocap/layout/layout_planning.h"

#include <QWidget>

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace mocap::ui {

/// The error-vs-marker-count curve of a layout plan (Wellein et al. 2007 Fig. 2), drawn with
/// QPainter as stacked plots sharing the marker-count axis: reconstruction RMSE (mm) above,
/// blend-weight MSE below and, when the layouts were judged on a blendshape rig, the rig-weight
/// MSE under them, each with the PFA, greedy and random-mean curves. The recommended size
/// is a dashed line, the selected size a band; a click (nearest size) or ←/→ selects a size among
/// those the plan's method has a layout for. Painting is O(#sizes).
class LayoutErrorPlot final : public QWidget
{
  Q_OBJECT

public:
  enum class Measure
  {
    ReconstructionRmse,
    BlendshapeMse,
    RigWeightMse,  ///< only with a rig measure (setPlan's `rig`)
  };
  enum class Curve
  {
    Pfa,
    Greedy,
    Random,
  };

  explicit LayoutErrorPlot(QWidget* parent = nullptr);

  /// Shows `plan` (the values are copied), with the rig measure of its layouts when given;
  /// selects the recommended size without emitting.
  void setPlan(const LayoutPlan& plan, const PlanRigErrors* rig = nullptr);
  /// Whether the rig-weight plot is shown.
  [[nodiscard]] bool showsRig() const { return m_hasRig; }
  void clear();

  /// Sizes a click can select (the plan's method has a layout there), ascending.
  [[nodiscard]] const std::vector<Eigen::Index>& selectableSizes() const { return m_selectable; }
  /// 0 when there is no plan or no recommendation.
  [[nodiscard]] Eigen::Index recommendedSize() const { return m_recommended; }
  [[nodiscard]] Eigen::Index selectedSize() const { return m_selected; }
  /// Selects `size` and emits sizeSelected when it changes; returns false (nothing changes) for a
  /// size that is not selectable.
  bool setSelectedSize(Eigen::Index size);

  /// The widget x coordinate of marker count `size` (for tests and clicks).
  [[nodiscard]] double xOf(Eigen::Index size) const;
  /// The drawn points of one curve in widget coordinates, one per size where it has a value.
  [[nodiscard]] std::vector<QPointF> points(Measure measure, Curve curve) const;

  [[nodiscard]] QSize sizeHint() const override { return {420, 360}; }
  [[nodiscard]] QSize minimumSizeHint() const override { return {240, 280}; }

signals:
  void sizeSelected(Eigen::Index size);

protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  bool event(QEvent* event) override;

private:
  /// One marker count: value[measure][curve], absent where the curve has none.
  struct Row
  {
    Eigen::Index markers = 0;
    std::array<std::array<std::optional<double>, 3>, 3> value;
  };

  [[nodiscard]] QRectF plotArea(Measure measure) const;
  [[nodiscard]] double maxValue(Measure measure) const;
  [[nodiscard]] double yOf(Measure measure, double value) const;
  void paintPlot(QPainter& painter, Measure measure) const;
  void paintLegend(QPainter& painter) const;
  void step(int direction);

  std::vector<Row> m_rows;
  std::vector<Eigen::Index> m_selectable;
  Eigen::Index m_recommended = 0;
  Eigen::Index m_selected = 0;
  bool m_hasRig = false;
};

} // namespace mocap::ui
