#pragma once
// What the marks over the panes mean: one row per overlay (its colour and line as drawn, and a
// sentence), and how to read a candidate's label ("A3 98/100/96"). The window docks it (View >
// Overlay legend); the pane's tooltip explains each candidate under the cursor.
#include <QWidget>

namespace omnitune {

class OverlayLegend : public QWidget {
    Q_OBJECT
public:
    explicit OverlayLegend(QWidget* parent = nullptr);

    // The legend as plain text (for tests and copying).
    QString text() const;
};

}  // namespace omnitune
