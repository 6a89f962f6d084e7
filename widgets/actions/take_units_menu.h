#pragma once

class QMenu;

namespace mocap::ui {

class TakeDocument;

/// Edit ▸ Positions Are In ▸ mm / cm / m: names the unit of the take's positions when its file
/// named none or the wrong one (the reader warns when the markers' span does not fit the unit).
/// Nothing is rescaled: one undoable step, recorded in the history as "name units" (from, to), so
/// a saved file says what was done. The checked entry follows the take. The studio's side of
/// `mocap convert --input-units`.
void addTakeUnitsMenu(QMenu& edit, TakeDocument& document);

} // namespace mocap::ui
