#pragma once
// The "Classes" group of the Colours tab: the colour classes in priority order (first wins),
// each with its display colour, name, role, an on/off tick and its share of the processed pixels
// of the frame on screen, and the buttons that add, remove and move a class and make the
// automatic first calibration. It only shows and asks: ColourEditor makes the edits.
#include "core/ColourClasses.h"
#include "calib/colour/ClassShares.h"

#include <QGroupBox>

class QListWidget;

namespace omnitune {

class ColourClassList : public QGroupBox {
    Q_OBJECT
public:
    explicit ColourClassList(QWidget* parent = nullptr);

    // Rebuilds the rows from `classes` with row `current` selected, without emitting signals.
    void setClasses(const ColourClasses& classes, int current);
    // Each row's text; with `shares` of these classes (null: none known) its share.
    void setShares(const ColourClasses& classes, const ClassShares* shares);

    QListWidget* list() const { return list_; }

signals:
    void currentChanged(int row);
    void enabledChanged(int row, bool on);
    void addRequested();
    void removeRequested();
    void moveRequested(int delta);  // -1: higher priority
    void autoRequested();

private:
    QListWidget* list_;
};

// A share in percent as the tab shows it; a few pixels (a ball) still show as a number.
QString colourSharePct(double pct);

}  // namespace omnitune
