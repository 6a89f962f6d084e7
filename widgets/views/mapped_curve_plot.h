#pragma once

#include <QString>
#include <QWidget>

#include <Eigen/Core>

namespace mocap::ui {

/// One retarget channel's curve against the frames, as the Retarget section shows it: the mapped
/// channel bright over the source shape's weight faint, both on one value axis that covers 0…1
/// and any value outside it, with the channel's name. Each pixel column draws the min–max of its
/// frames, so painting is O(#frames + width).
class MappedCurvePlot final : public QWidget
{
  Q_OBJECT

public:
  explicit MappedCurvePlot(QWidget* parent = nullptr);

  /// `mapped` the channel, `source` the weight it is made from (may be empty), named `label`.
  void setCurves(Eigen::VectorXd mapped, Eigen::VectorXd source, const QString& label);
  void clear();
  [[nodiscard]] const Eigen::VectorXd& mapped() const { return m_mapped; }
  [[nodiscard]] QSize sizeHint() const override { return {260, 90}; }

protected:
  void paintEvent(QPaintEvent* event) override;

private:
  Eigen::VectorXd m_mapped;
  Eigen::VectorXd m_source;
  QString m_label;
};

} // namespace mocap::ui
