#pragma once

#include "mocap/tracking/swap_detection.h"

#include <QDialog>

#include <vector>

class QListWidget;

namespace mocap::ui {

/// Lists detected label swaps for review: each can be accepted (checked, the default) or
/// rejected; double-clicking one shows its frame. The caller repairs the accepted ones.
class SwapReviewDialog final : public QDialog
{
  Q_OBJECT

public:
  SwapReviewDialog(const Take& take, std::vector<LabelSwap> swaps, QWidget* parent = nullptr);

  [[nodiscard]] std::vector<LabelSwap> acceptedSwaps() const;

signals:
  void frameRequested(Eigen::Index frame);

private:
  std::vector<LabelSwap> m_swaps;
  QListWidget* m_list = nullptr;
};

} // namespace mocap::ui
