#pragma once

class QTableView;

namespace mocap::ui {

/// Makes `column` of `view`, which shows marker labels, as wide as a long label of the
/// sample ("section14-30", beside a check box when `checkable`) and elides longer ones in the
/// middle (they differ at their end: "Channel101", "Channel102"): labels
/// from other systems ("Skeleton_LShoulder2") would otherwise push the columns after it out of a
/// narrow dock. The model gives the whole label as the cell's tooltip. O(1).
void limitLabelColumn(QTableView& view, int column, bool checkable);

} // namespace mocap::ui
