#pragma once

class QWidget;

namespace mocap::ui {

/// Every form inside `panel` puts a field wider than the room beside its label under the label,
/// rather than pushing the panel's buttons out of view sideways in a narrow dock (about 310 px
/// when the studio first opens on a 1280×800 screen). Rows of buttons use FlowLayout for the
/// same reason. O(#widgets in the panel).
void wrapLongFormRows(QWidget& panel);

} // namespace mocap::ui
