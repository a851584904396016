#pragma once
// An editor's mode on the panes (radial sensors R, reference regions K): the checkable menu
// action that switches it, and what switching it does to the panes. Each editor keeps its own
// drag and its message; only this part was the same in each.
#include "widgets/PaneInput.h"

#include <QAction>
#include <QKeySequence>
#include <QMenu>

#include <vector>

namespace omnitune {

// A checkable action under `key`; toggling it calls `setEditing` on `editor`.
template <class Editor>
QAction* addEditModeAction(QMenu* menu, Editor* editor, void (Editor::*setEditing)(bool), const QString& text,
                           const QString& objectName, const QKeySequence& key, const QString& statusTip)
{
    QAction* action = menu->addAction(text);
    action->setObjectName(objectName);
    action->setCheckable(true);
    action->setShortcut(key);
    action->setStatusTip(statusTip);
    QObject::connect(action, &QAction::toggled, editor, setEditing);
    return action;
}

// The editor takes the left button (or gives it back), its action shows the mode, and what it
// draws over the panes shows only while it is on.
inline void showEditMode(PipelineView* view, const QObject* editor, bool on, QAction* modeAction,
                         const std::vector<QWidget*>& sketches)
{
    holdPanes(view, editor, on);
    if (modeAction) modeAction->setChecked(on);
    for (QWidget* w : sketches) w->setVisible(on);
}

}  // namespace omnitune
