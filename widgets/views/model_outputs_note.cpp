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
  setText(m_document.showsModelOutputs() ? tr("%1 shown; never cleaned").arg(outputs)
                                         : tr("%1 hidden; View ▸ Show Model Outputs").arg(outputs));
  setToolTip(tr("Model outputs are joint angles, forces, moments and powers the capture software stored as points. "
                "They are kept and saved, but not cleaned, gap-listed or counted in statistics."));
}

} // namespace mocap::ui
