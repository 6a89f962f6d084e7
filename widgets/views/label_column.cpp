#include "views/label_column.h"

#include <QHeaderView>
#include <QStyle>
#include <QStyledItemDelegate>
#include <QTableView>

namespace mocap::ui {

namespace {

/// Elides a label in its middle: labels from other systems differ at their end ("Channel101",
/// "Channel102"), which eliding at the right would hide.
class MiddleElidingDelegate final : public QStyledItemDelegate
{
public:
  using QStyledItemDelegate::QStyledItemDelegate;

protected:
  void initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const override
  {
    QStyledItemDelegate::initStyleOption(option, index);
    option->textElideMode = Qt::ElideMiddle;
  }
};

} // namespace

void limitLabelColumn(QTableView& view, int column, bool checkable)
{
  const int indicator = checkable ? view.style()->pixelMetric(QStyle::PM_IndicatorWidth) : 0;
  const int width = indicator + view.fontMetrics().horizontalAdvance(QStringLiteral("section14-30"));
  QHeaderView* header = view.horizontalHeader();
  header->setSectionResizeMode(column, QHeaderView::Interactive);  // a user may still widen it
  header->resizeSection(column, width);
  view.setItemDelegateForColumn(column, new MiddleElidingDelegate(&view));
}

} // namespace mocap::ui
