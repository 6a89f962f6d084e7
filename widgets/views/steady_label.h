#pragma once

#include <QString>

class QLabel;

namespace mocap::ui {

/// Fixes `label`'s size to fit `widest` (and at least `minimumWidth`). Qt relayouts a whole
/// window each time a label whose size may change gets new text (3 ms a frame under Xvfb when
/// the frame readouts did, while scrubbing); a label of fixed size does not. For readouts that
/// change every frame: call again when what fits changes (a new take).
void fixLabelSizeFor(QLabel& label, const QString& widest, int minimumWidth = 0);

} // namespace mocap::ui
