#include "views/model_outputs_note.h"

#include "document/take_document.h"

#include "mocap/model/marker_points.h"

namespace mocap::ui {

ModelOutputsNote::ModelOutputsNote(TakeDocument& document, QWidget* parent) : QLabel(parent), m_document(document)
{
  setObjectName(QStringLiteral("modelOutputsNote"));
  connect(&document, &TakeDocument::takeReset, this, &ModelOutputsNote::refresh);
  connect(&document, &TakeDocument::markersChanged, this, &ModelOutputsNote::refresh);
  connect(&document, &TakeDocument::visibilityChanged, this, &ModelOutputsNote::refresh);
  refresh();
}

void ModelOutputsNote::refresh()
{
  const QString outputs = QString::fromStdString(describeModelOutputs(m_document.take()));
  setVisible(!outputs.isEmpty());
  if (outputs.isEmpty())
    return;
  // Short, as the status bar's messages ("Saved …") share its width with the permanent widgets
  // (they were cut to "Saved /tmp/walk/pig_c" at the first-run size); the kinds are in the tooltip.
  const QString head = outputs.section(QStringLiteral(" ("), 0, 0);  // "34 model outputs"
  const bool shown = m_document.showsModelOutputs();
  setText(shown ? tr("%1 shown").arg(head) : tr("%1 hidden").arg(head));
  setToolTip((shown ? tr("%1 shown; never cleaned") : tr("%1 hidden; View ▸ Show Model Outputs")).arg(outputs) +
             QStringLiteral("\n") +
             tr("Model outputs are joint angles, forces, moments, powers and virtual points (a model's segment "
                "axes, centre of mass) the capture software stored as points. They are kept and saved, but not "
                "cleaned, gap-listed or counted in statistics."));
}

} // namespace mocap::ui
