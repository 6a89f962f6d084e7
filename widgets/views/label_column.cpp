#include "views/label_column.h"

#include <QHeaderView>
#include <QStyle>
#include <QTableView>

namespace mocap::ui {

void limitLabelColumn(QTableView& view, int column, bool checkable)
{
  const int indicator = checkable ? view.style()->pixelMetric(QStyle::PM_IndicatorWidth) : 0;
  const int width = indicator + view.fontMetrics().horizontalAdvance(QStringLiteral("section14-30"));
  QHeaderView* header = view.horizontalHeader();
  header->setSectionResizeMode(column, QHeaderView::Interactive);  // a user may still widen it
  header->resizeSection(column, width);
  view.setTextElideMode(Qt::ElideRight);
}

} // namespace mocap::ui
