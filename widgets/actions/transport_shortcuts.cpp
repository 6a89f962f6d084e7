#include "actions/transport_shortcuts.h"

#include "document/take_document.h"
#include "views/timeline_widget.h"

#include <QAction>
#include <QKeySequence>
#include <QWidget>

namespace mocap::ui {

void addTransportShortcuts(QWidget& window, TakeDocument& document, TimelineWidget& timeline)
{
  auto add = [&window](const QKeySequence& keys, auto slot) {
    auto* action = new QAction(&window);
    action->setShortcut(keys);
    action->setShortcutContext(Qt::WindowShortcut);
    QObject::connect(action, &QAction::triggered, &window, slot);
    window.addAction(action);
  };
  TimelineWidget* line = &timeline;
  TakeDocument* take = &document;
  add(QKeySequence(Qt::Key_Space), [line] { line->togglePlaying(); });
  add(QKeySequence(Qt::Key_Right), [line] { line->step(1); });
  add(QKeySequence(Qt::Key_Left), [line] { line->step(-1); });
  add(QKeySequence(Qt::SHIFT | Qt::Key_Right), [line] { line->step(10); });
  add(QKeySequence(Qt::SHIFT | Qt::Key_Left), [line] { line->step(-10); });
  add(QKeySequence(Qt::Key_Home), [take] { take->setCurrentFrame(0); });
  add(QKeySequence(Qt::Key_End), [take] { take->setCurrentFrame(take->take().frameCount() - 1); });
  add(QKeySequence(Qt::Key_PageDown), [line] { line->jumpToGap(1); });
  add(QKeySequence(Qt::Key_PageUp), [line] { line->jumpToGap(-1); });
  add(QKeySequence(Qt::CTRL | Qt::Key_PageDown), [line] { line->jumpToFlag(1); });
  add(QKeySequence(Qt::CTRL | Qt::Key_PageUp), [line] { line->jumpToFlag(-1); });
}

} // namespace mocap::ui
