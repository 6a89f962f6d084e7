#pragma once

#include <QLayout>
#include <QList>

namespace mocap::ui {

/// Lays its widgets out left to right at their size hints and starts a new line where the next
/// one would pass the right edge: a row of buttons that wraps in a narrow dock instead of making
/// it scroll sideways (the side docks are about 310 px wide when the studio first opens on a
/// 1280×800 screen). Its minimum width is its widest item's. O(#items) per layout pass.
class FlowLayout final : public QLayout
{
public:
  /// With a parent widget it is that widget's layout (with the style's margins); without, it
  /// goes into another layout (no margins).
  explicit FlowLayout(QWidget* parent = nullptr);
  ~FlowLayout() override;
  FlowLayout(const FlowLayout&) = delete;
  FlowLayout& operator=(const FlowLayout&) = delete;

  void addItem(QLayoutItem* item) override;
  [[nodiscard]] int count() const override;
  [[nodiscard]] QLayoutItem* itemAt(int index) const override;
  QLayoutItem* takeAt(int index) override;
  [[nodiscard]] Qt::Orientations expandingDirections() const override;
  [[nodiscard]] bool hasHeightForWidth() const override;
  [[nodiscard]] int heightForWidth(int width) const override;
  [[nodiscard]] QSize minimumSize() const override;
  [[nodiscard]] QSize sizeHint() const override;
  void setGeometry(const QRect& rect) override;

private:
  /// Lays the items out in `rect`, moving them only when `apply`; returns the height taken.
  int arrange(const QRect& rect, bool apply) const;
  [[nodiscard]] int gap() const;

  QList<QLayoutItem*> m_items;
};

} // namespace mocap::ui
