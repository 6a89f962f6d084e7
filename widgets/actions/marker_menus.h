#pragma once

#include <QString>

#include <functional>

class QMenuBar;

namespace mocap::ui {

class LabellingActions;
class MarkerEditActions;
class MarkerView3d;
class ReferenceMarkerActions;
class TakeDocument;

/// The Marker menu: delete, average and swap markers (MarkerEditActions), the reference markers
/// (ReferenceMarkerActions), hide the selected and show all.
void addMarkerMenu(QMenuBar& bar, TakeDocument& document, MarkerEditActions& edits, ReferenceMarkerActions& reference);

/// The Label menu: Track and Label, Fix Swaps (LabellingActions) and Assign Label by Clicking (A),
/// a mode of `view` in which a clicked point takes the selected marker's label; `message` says
/// how to use the mode while it is on.
void addLabelMenu(QMenuBar& bar, LabellingActions& labelling, MarkerEditActions& edits, MarkerView3d& view,
                  const std::function<void(const QString&, int)>& message);

} // namespace mocap::ui
