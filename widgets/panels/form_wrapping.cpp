#include "panels/form_wrapping.h"

#include <QFormLayout>
#include <QWidget>

namespace mocap::ui {

void wrapLongFormRows(QWidget& panel)
{
  for (QFormLayout* form : panel.findChildren<QFormLayout*>())  // nested layouts included
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
}

} // namespace mocap::ui
