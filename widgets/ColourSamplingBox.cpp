#include "widgets/ColourSamplingBox.h"

#include "widgets/ColourSampler.h"
#include "widgets/ConfigDocument.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>

#include <tuple>

namespace omnitune {

namespace {

const QString kOutlierKey = QStringLiteral("colors.sample_outlier_percent");

}  // namespace

ColourSamplingBox::ColourSamplingBox(ConfigDocument* doc, ColourSampler* sampler, QWidget* parent)
    : QGroupBox(tr("Sampling on the panes"), parent), doc_(doc), sampler_(sampler), sampleButton_(new QToolButton),
      tool_(new QComboBox), radius_(new QSpinBox), tolH_(new QSpinBox), tolS_(new QSpinBox), tolV_(new QSpinBox),
      outliers_(new QDoubleSpinBox)
{
    auto* sl = new QFormLayout(this);
    sampleButton_->setText(tr("Sample (C)"));
    sampleButton_->setObjectName("sampleButton");
    sampleButton_->setCheckable(true);
    sampleButton_->setToolTip(tr("Left button on any pane: drag or click adds the pixels' colours to the selected "
                                 "class's box; Ctrl removes them; Shift drags a rectangle; middle button pans"));
    tool_->addItems({tr("Brush"), tr("Magic wand (W)")});
    tool_->setObjectName("tool");
    auto* toolRow = new QHBoxLayout;
    toolRow->addWidget(sampleButton_);
    toolRow->addWidget(tool_, 1);
    sl->addRow(toolRow);
    radius_->setRange(0, ColourSampler::kMaxBrushRadius);
    radius_->setValue(sampler_->brushRadius());
    radius_->setSuffix(tr(" px"));
    radius_->setObjectName("brushRadius");
    radius_->setToolTip(tr("Brush radius in image pixels ([ and ] change it); 0 samples single pixels"));
    sl->addRow(tr("Brush radius"), radius_);
    auto* tolRow = new QHBoxLayout;
    const WandTolerance wand = sampler_->wandTolerance();
    for (auto [box, value, top, tip] : {std::tuple{tolH_, wand.h, 90, tr("Hue steps (0..179 scale) a pixel may differ from the clicked one")},
                                        std::tuple{tolS_, wand.s, 255, tr("Saturation steps a pixel may differ from the clicked one")},
                                        std::tuple{tolV_, wand.v, 255, tr("Value steps a pixel may differ from the clicked one")}}) {
        box->setRange(0, top);
        box->setValue(value);
        box->setToolTip(tip);
        tolRow->addWidget(box);
    }
    sl->addRow(tr("Wand ± H S V"), tolRow);
    outliers_->setRange(0.0, 25.0);
    outliers_->setDecimals(1);
    outliers_->setSingleStep(0.5);
    outliers_->setSuffix(tr(" %"));
    outliers_->setValue(doc_->config().colors.sampleOutlierPct);
    outliers_->setObjectName("outlierPct");
    outliers_->setToolTip(tr("Share of a stroke's samples ignored at each end of H, S and V (stray pixels at a ball's "
                             "blurred edge); 0 covers every sample. Saved in the config: colors.sample_outlier_percent"));
    sl->addRow(tr("Ignore outliers"), outliers_);

    connect(sampleButton_, &QToolButton::toggled, sampler_, &ColourSampler::setSampling);
    connect(sampler_, &ColourSampler::samplingChanged, sampleButton_, &QToolButton::setChecked);
    connect(tool_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
            [this](int i) { sampler_->setTool(i == 1 ? ColourSampler::Tool::Wand : ColourSampler::Tool::Brush); });
    connect(sampler_, &ColourSampler::toolChanged, this, [this](ColourSampler::Tool t) {
        tool_->setCurrentIndex(t == ColourSampler::Tool::Wand ? 1 : 0);
    });
    connect(radius_, QOverload<int>::of(&QSpinBox::valueChanged), sampler_, &ColourSampler::setBrushRadius);
    connect(sampler_, &ColourSampler::brushRadiusChanged, radius_, &QSpinBox::setValue);
    for (QSpinBox* s : {tolH_, tolS_, tolV_})
        connect(s, QOverload<int>::of(&QSpinBox::valueChanged), this, [this] {
            WandTolerance t = sampler_->wandTolerance();
            t.h = tolH_->value();
            t.s = tolS_->value();
            t.v = tolV_->value();
            sampler_->setWandTolerance(t);
        });
    connect(outliers_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double pct) {
        if (pct != doc_->config().colors.sampleOutlierPct) doc_->setValue(kOutlierKey, pct);
    });
    connect(doc_, &ConfigDocument::changed, this, [this] {
        const QSignalBlocker block(outliers_);
        outliers_->setValue(doc_->config().colors.sampleOutlierPct);
    });
}

}  // namespace omnitune
