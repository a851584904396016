#pragma once
// The "Sampling on the panes" group of the Colours tab: the Sample toggle, brush or magic wand,
// the brush radius, the wand's tolerances and the outlier share a stroke ignores. Every control
// sets the ColourSampler's state and follows it (the C, W, [ and ] shortcuts change it too);
// the outlier share is the config key colors.sample_outlier_percent (an edit is an undo step).
#include <QGroupBox>

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;
class QToolButton;

namespace omnitune {

class ColourSampler;
class ConfigDocument;

class ColourSamplingBox : public QGroupBox {
    Q_OBJECT
public:
    // `sampler` must outlive the box.
    // `doc` and `sampler` must outlive the box.
    ColourSamplingBox(ConfigDocument* doc, ColourSampler* sampler, QWidget* parent = nullptr);

private:
    ConfigDocument* doc_;
    ColourSampler* sampler_;
    QToolButton* sampleButton_;
    QComboBox* tool_;
    QSpinBox* radius_;
    QSpinBox* tolH_;
    QSpinBox* tolS_;
    QSpinBox* tolV_;
    QDoubleSpinBox* outliers_;
};

}  // namespace omnitune
