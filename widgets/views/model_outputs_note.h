#pragma once

#include <QLabel>

namespace mocap::ui {

class TakeDocument;

/// The status-bar note on the open take's model outputs (marker_points.h: angles, forces...
/// a C3D file stores as points): "34 model outputs hidden" or "… shown", the kinds and View ▸ Show
/// Model Outputs in its tooltip. Hidden when the take has none.
/// Follows the document (a new take, markers added or removed, the filter toggled).
class ModelOutputsNote final : public QLabel
{
  Q_OBJECT

public:
  explicit ModelOutputsNote(TakeDocument& document, QWidget* parent = nullptr);

private:
  void refresh();

  TakeDocument& m_document;
};

} // namespace mocap::ui
