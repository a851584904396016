#include "widgets/ColourBoxEditor.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>

namespace omnitune {

namespace {

int& field(HsvRange& r, ColourBoxEditor::Bound b)
{
    switch (b) {
    case ColourBoxEditor::HMin: return r.hMin;
    case ColourBoxEditor::HMax: return r.hMax;
    case ColourBoxEditor::SMin: return r.sMin;
    case ColourBoxEditor::SMax: return r.sMax;
    case ColourBoxEditor::VMin: return r.vMin;
    case ColourBoxEditor::VMax: break;
    }
    return r.vMax;
}

}  // namespace

ColourBoxEditor::ColourBoxEditor(QWidget* parent) : QWidget(parent), enabled_(new QCheckBox(tr("Box used"), this)),
                                                                       wrapNote_(new QLabel(this))
{
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setVerticalSpacing(2);
    const QString names[kBounds] = {tr("H min"), tr("H max"), tr("S min"), tr("S max"), tr("V min"), tr("V max")};
    const QString keys[kBounds] = {"hMin", "hMax", "sMin", "sMax", "vMin", "vMax"};
    const QString tips[kBounds] = {
        tr("Lowest hue, OpenCV scale 0..179 (red 0, yellow 30, green 60, cyan 90, blue 120, magenta 150). "
           "Above H max the box wraps through 0: 170..10 is red."),
        tr("Highest hue, 0..179; below H min the box wraps through 0"),
        tr("Lowest saturation 0..255: higher leaves out pale and grey pixels"),
        tr("Highest saturation 0..255"),
        tr("Lowest value (brightness) 0..255: higher leaves out dark pixels and shadows"),
        tr("Highest value (brightness) 0..255")};
    grid->addWidget(enabled_, 0, 0, 1, 3);
    for (int i = 0; i < kBounds; ++i) {
        const Bound b = Bound(i);
        auto* s = new QSlider(Qt::Horizontal, this);
        auto* n = new QSpinBox(this);
        const int top = i < 2 ? 179 : 255;
        s->setRange(0, top);
        n->setRange(0, top);
        s->setObjectName(keys[i] + "Slider");
        n->setObjectName(keys[i]);
        n->setKeyboardTracking(false);  // typing "120" is one edit, not 1, 12 and 120
        s->setToolTip(tips[i]);
        n->setToolTip(tips[i]);
        sliders_[std::size_t(i)] = s;
        spins_[std::size_t(i)] = n;
        grid->addWidget(new QLabel(names[i], this), i + 1, 0);
        grid->addWidget(s, i + 1, 1);
        grid->addWidget(n, i + 1, 2);
        connect(s, &QSlider::valueChanged, this, [this, b, s](int v) { onValue(b, v, !s->isSliderDown()); });
        connect(s, &QSlider::sliderReleased, this, [this, b, s] { onValue(b, s->value(), true); });
        connect(n, QOverload<int>::of(&QSpinBox::valueChanged), this, [this, b](int v) { onValue(b, v, true); });
    }
    wrapNote_->setWordWrap(true);
    wrapNote_->setObjectName("wrapNote");
    grid->addWidget(wrapNote_, kBounds + 1, 0, 1, 3);
    connect(enabled_, &QCheckBox::toggled, this, [this](bool on) {
        if (showing_) return;
        box_.enabled = on;
        emit edited(box_, true);
    });
    show(box_);
}

void ColourBoxEditor::setBox(const HsvRange& box)
{
    box_ = box;
    show(box_);
}

void ColourBoxEditor::show(const HsvRange& box)
{
    showing_ = true;
    enabled_->setChecked(box.enabled);
    for (int i = 0; i < kBounds; ++i) {
        HsvRange copy = box;
        const int v = field(copy, Bound(i));
        const QSignalBlocker a(sliders_[std::size_t(i)]);
        const QSignalBlocker b(spins_[std::size_t(i)]);
        // A slider being dragged keeps its knob under the mouse.
        if (!sliders_[std::size_t(i)]->isSliderDown()) sliders_[std::size_t(i)]->setValue(v);
        spins_[std::size_t(i)]->setValue(v);
    }
    wrapNote_->setText(box.hMin > box.hMax ? tr("Hue wraps through 0: %1..179 and 0..%2").arg(box.hMin).arg(box.hMax)
                                           : QString());
    wrapNote_->setVisible(box.hMin > box.hMax);
    showing_ = false;
}

void ColourBoxEditor::onValue(Bound b, int value, bool finished)
{
    if (showing_) return;
    HsvRange next = box_;
    field(next, b) = value;
    // S and V: min never above max (an empty box); the other bound follows. Hue may wrap.
    if (b == SMin && next.sMax < value) next.sMax = value;
    if (b == SMax && next.sMin > value) next.sMin = value;
    if (b == VMin && next.vMax < value) next.vMax = value;
    if (b == VMax && next.vMin > value) next.vMin = value;
    const bool same = next.hMin == box_.hMin && next.hMax == box_.hMax && next.sMin == box_.sMin &&
                      next.sMax == box_.sMax && next.vMin == box_.vMin && next.vMax == box_.vMax;
    box_ = next;
    show(box_);
    if (same && !finished) return;
    emit edited(box_, finished);
}

}  // namespace omnitune
