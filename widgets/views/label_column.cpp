#include "views/label_column.h"

#include <QAbstractItemModel>
#include <QApplication>
#include <QHash>
#include <QHeaderView>
#include <QStyle>
#include <QStyledItemDelegate>
#include <QTableView>

#include <algorithm>

namespace mocap::ui {

namespace {

/// Whether `c` ends a namespace in a label ("Human3:", "Skeleton_", "section14-").
bool isSeparator(QChar c)
{
  return !c.isLetterOrNumber();
}

/// Labels of other systems share namespaces ("Human3:LLSP", "Human3:ULSP", "Tools:TOOL1Y"): eliding
/// in the middle kept the shared start and lost what tells them apart ("Hum…LSP" twice). For each
/// label of a column: how many of its first characters, up to a separator, it shares with
/// another label of the column, the part an elided label can drop first.
class SharedPrefixes final
{
public:
  /// The shared prefix's length of the label at `index`.
  int of(const QModelIndex& index)
  {
    if (m_model != index.model()) {
      watch(*index.model());
      m_stale = true;
    }
    if (m_stale || m_column != index.column()) {
      recompute(*index.model(), index.column());
      m_stale = false;
    }
    return m_shared.value(index.data().toString(), 0);
  }

private:
  // Marks the prefixes stale whenever the labels may have changed.
  void watch(const QAbstractItemModel& model)
  {
    QObject& context = m_connections;
    if (m_model)
      QObject::disconnect(m_model, nullptr, &context, nullptr);
    const auto stale = [this] { m_stale = true; };
    QObject::connect(&model, &QAbstractItemModel::modelReset, &context, stale);
    QObject::connect(&model, &QAbstractItemModel::dataChanged, &context, stale);
    QObject::connect(&model, &QAbstractItemModel::rowsInserted, &context, stale);
    QObject::connect(&model, &QAbstractItemModel::rowsRemoved, &context, stale);
    QObject::connect(&model, &QAbstractItemModel::layoutChanged, &context, stale);
  }
  // Sorted, a label shares its longest prefix with a neighbour. O(#rows · log #rows).
  void recompute(const QAbstractItemModel& model, int column)
  {
    QStringList labels;
    for (int row = 0; row < model.rowCount(); ++row)
      labels << model.index(row, column).data().toString();
    labels.sort();
    m_shared.clear();
    for (int i = 0; i + 1 < labels.size(); ++i) {
      const int shared = namespaceLength(labels[i], labels[i + 1]);
      for (const QString& label : {labels[i], labels[i + 1]})
        m_shared[label] = std::max(m_shared.value(label, 0), shared);
    }
    m_model = &model;
    m_column = column;
  }
  // The common prefix of a and b cut back to just after its last separator.
  static int namespaceLength(const QString& a, const QString& b)
  {
    const int common = static_cast<int>(std::mismatch(a.begin(), a.begin() + std::min(a.size(), b.size()), b.begin()).first -
                                        a.begin());
    for (int end = common; end > 0; --end)
      if (isSeparator(a[end - 1]) && end < a.size())
        return end;
    return 0;
  }

  const QAbstractItemModel* m_model = nullptr;
  int m_column = -1;
  bool m_stale = true;
  QHash<QString, int> m_shared;
  QObject m_connections;  // their context: they end with this object
};

/// Elides a label that does not fit: first the namespace it shares with other labels of the column
/// ("Human3:LLSP" → "…LLSP"), then in the middle (labels from other systems differ at their end:
/// "Channel101", "Channel102"), which eliding at the right would hide.
class LabelElidingDelegate final : public QStyledItemDelegate
{
public:
  using QStyledItemDelegate::QStyledItemDelegate;

protected:
  void initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const override
  {
    QStyledItemDelegate::initStyleOption(option, index);
    option->textElideMode = Qt::ElideMiddle;
    if (option->rect.isEmpty() || option->text.isEmpty())
      return;  // a size hint: the whole label
    const QStyle* style = option->widget ? option->widget->style() : QApplication::style();
    const int margin = style->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, option->widget) + 1;
    const int room = style->subElementRect(QStyle::SE_ItemViewItemText, option, option->widget).width() - 2 * margin;
    if (option->fontMetrics.horizontalAdvance(option->text) <= room)
      return;
    if (const int shared = m_prefixes.of(index); shared > 0)
      option->text = QStringLiteral("…") + option->text.mid(shared);
  }

private:
  mutable SharedPrefixes m_prefixes;
};

} // namespace

void limitLabelColumn(QTableView& view, int column, bool checkable)
{
  const int indicator = checkable ? view.style()->pixelMetric(QStyle::PM_IndicatorWidth) : 0;
  const int width = indicator + view.fontMetrics().horizontalAdvance(QStringLiteral("section14-30"));
  QHeaderView* header = view.horizontalHeader();
  header->setSectionResizeMode(column, QHeaderView::Interactive);  // a user may still widen it
  header->resizeSection(column, width);
  view.setItemDelegateForColumn(column, new LabelElidingDelegate(&view));
}

} // namespace mocap::ui
