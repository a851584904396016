#pragma once
// How an editor of the panes (MaskEditor, RadialSensorEditor) takes the left button from
// PipelineView: the view reports presses, drags and releases to whichever editor
// setPaneEditor() named, and each editor acts only on its own turn.
#include "widgets/PipelineView.h"

namespace omnitune {

template <class Editor>
void connectPaneInput(PipelineView* view, Editor* editor, void (Editor::*pressed)(QPointF),
                      void (Editor::*dragged)(QPointF), void (Editor::*released)(QPointF))
{
    const auto route = [view, editor](void (Editor::*handler)(QPointF)) {
        return [view, editor, handler](QPointF p) {
            if (view->paneEditor() == editor) (editor->*handler)(p);
        };
    };
    QObject::connect(view, &PipelineView::editorPressed, editor, route(pressed));
    QObject::connect(view, &PipelineView::editorDragged, editor, route(dragged));
    QObject::connect(view, &PipelineView::editorReleased, editor, route(released));
}

// Gives the left button to `editor` (on) or back to panning, unless another editor holds it.
inline void holdPanes(PipelineView* view, const QObject* editor, bool on)
{
    if (on)
        view->setPaneEditor(editor);
    else if (view->paneEditor() == editor)
        view->setPaneEditor(nullptr);
}

}  // namespace omnitune
