#pragma once
// One HSV box of a colour class: H, S and V min-max, each with a slider and a spin box, and
// whether the box is used. Hue min above hue max is allowed (the box wraps through 0, red);
// S and V min never pass their max (moving one pushes the other), so the editor cannot make
// the empty box the config refuses. Reports every change with whether it ends a gesture: a
// slider drag reports live changes and one finished change on release, so the caller can make
// the whole drag one undo step.
#include "core/HsvRange.h"

#include <QWidget>

#include <array>

class QCheckBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace omnitune {

class ColourBoxEditor : public QWidget {
    Q_OBJECT
public:
    enum Bound { HMin, HMax, SMin, SMax, VMin, VMax };
    static constexpr int kBounds = 6;

    explicit ColourBoxEditor(QWidget* parent = nullptr);

    // Shows `box` without reporting a change.
    void setBox(const HsvRange& box);
    HsvRange box() const { return box_; }
    QSlider* slider(Bound b) const { return sliders_[std::size_t(b)]; }
    QSpinBox* spinBox(Bound b) const { return spins_[std::size_t(b)]; }
    QCheckBox* enabledBox() const { return enabled_; }

signals:
    // `finished`: false while a slider is being dragged, true for the change that ends a gesture.
    void edited(const omnitune::HsvRange& box, bool finished);

private:
    void onValue(Bound b, int value, bool finished);
    void show(const HsvRange& box);  // widgets follow `box`, no signal

    HsvRange box_;
    std::array<QSlider*, kBounds> sliders_{};
    std::array<QSpinBox*, kBounds> spins_{};
    QCheckBox* enabled_;
    QLabel* wrapNote_;
    bool showing_ = false;
};

}  // namespace omnitune
