#include "views/sample_colors.h"

#include <QCoreApplication>
#include <QStringList>

namespace mocap::ui {

SampleMark primaryMark(SampleState state)
{
  switch (state.origin()) {
  case SampleOrigin::Filled: return SampleMark::Filled;
  case SampleOrigin::Edited: return SampleMark::Edited;
  case SampleOrigin::Measured: break;
  }
  return state.has(SampleOperation::Smoothed) ? SampleMark::Smoothed : SampleMark::None;
}

SampleMark secondaryMark(SampleState state)
{
  const bool made = state.origin() != SampleOrigin::Measured;
  return made && state.has(SampleOperation::Smoothed) ? SampleMark::Smoothed : SampleMark::None;
}

QColor markColor(SampleMark mark)
{
  const ColorScheme& scheme = colorScheme();
  switch (mark) {
  case SampleMark::None: return scheme.original;
  case SampleMark::Smoothed: return scheme.smoothed;
  case SampleMark::Filled: return scheme.filled;
  case SampleMark::Edited: return scheme.edited;
  }
  return scheme.original;
}

QColor stateColor(SampleState state)
{
  return markColor(primaryMark(state));
}

QString operationsText(SampleState state)
{
  QStringList names;
  if (state.has(SampleOperation::Smoothed))
    names << QCoreApplication::translate("SampleState", "smoothed");
  if (state.has(SampleOperation::Stabilized))
    names << QCoreApplication::translate("SampleState", "stabilized");
  return names.join(QStringLiteral(", "));
}

QString stateText(SampleState state)
{
  QString origin;
  switch (state.origin()) {
  case SampleOrigin::Measured: origin = QCoreApplication::translate("SampleState", "measured"); break;
  case SampleOrigin::Filled: origin = QCoreApplication::translate("SampleState", "filled"); break;
  case SampleOrigin::Edited: origin = QCoreApplication::translate("SampleState", "edited"); break;
  }
  const QString operations = operationsText(state);
  return operations.isEmpty() ? origin : origin + QStringLiteral(", ") + operations;
}

QColor selectionColor()
{
  return colorScheme().selection;
}

} // namespace mocap::ui
