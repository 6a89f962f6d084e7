#include "dialogs/swap_review_dialog.h"

#include "mocap/base/length_unit.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace mocap::ui {

SwapReviewDialog::SwapReviewDialog(const Take& take, std::vector<LabelSwap> swaps, QWidget* parent)
    : QDialog(parent), m_swaps(std::move(swaps))
{
  setWindowTitle(tr("Review Label Swaps"));
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(new QLabel(tr("%n swap(s) found. Uncheck the ones to leave as they are; double-click one to see "
                                  "its frame.",
                                  nullptr, static_cast<int>(m_swaps.size())),
                               this));
  m_list = new QListWidget(this);
  const double mm = millimetresPer(take.units());
  for (const LabelSwap& swap : m_swaps) {
    auto* item = new QListWidgetItem(tr("Frame %1: %2 ↔ %3 (jump %4 mm, %5 mm when exchanged)")
                                         .arg(static_cast<qlonglong>(take.firstFrame() + swap.frame))
                                         .arg(QString::fromStdString(take.label(swap.first)),
                                              QString::fromStdString(take.label(swap.second)))
                                         .arg(swap.jump * mm, 0, 'f', 1)
                                         .arg(swap.explained * mm, 0, 'f', 1),
                                     m_list);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(Qt::Checked);
  }
  connect(m_list, &QListWidget::itemDoubleClicked, this, [this](QListWidgetItem* item) {
    emit frameRequested(m_swaps[static_cast<std::size_t>(m_list->row(item))].frame);
  });
  layout->addWidget(m_list);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Repair Checked"));
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  layout->addWidget(buttons);
  resize(560, 360);
}

std::vector<LabelSwap> SwapReviewDialog::acceptedSwaps() const
{
  std::vector<LabelSwap> accepted;
  for (int row = 0; row < m_list->count(); ++row)
    if (m_list->item(row)->checkState() == Qt::Checked)
      accepted.push_back(m_swaps[static_cast<std::size_t>(row)]);
  return accepted;
}

} // namespace mocap::ui
