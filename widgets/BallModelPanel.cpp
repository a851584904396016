#include "widgets/BallModelPanel.h"

#include "widgets/ConfigDocument.h"
#include "widgets/CurveFitPlot.h"
#include "widgets/TruthDocument.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace omnitune {

BallModelPanel::BallModelPanel(ConfigDocument* doc, const TruthDocument* truth, QWidget* parent)
    : QWidget(parent), doc_(doc), truth_(truth), plot_(new CurveFitPlot(this)), status_(new QLabel(this)),
      useDetections_(new QCheckBox(tr("Include accepted detections of the last whole-session run"), this)),
      useDirection_(new QCheckBox(tr("Per-direction correction (off-axis mirror)"), this)),
      fitButton_(new QPushButton(tr("Fit"), this)), applyButton_(new QPushButton(tr("Apply to config"), this))
{
    setObjectName(QStringLiteral("ballModelPanel"));
    plot_->setObjectName(QStringLiteral("ballModelPlot"));
    status_->setObjectName(QStringLiteral("ballModelStatus"));
    status_->setWordWrap(true);
    // Room for the fit, its span and the direction note: a wrapped label in a dock is otherwise
    // given one line and cut.
    status_->setMinimumHeight(4 * status_->fontMetrics().lineSpacing());
    useDetections_->setChecked(true);
    useDetections_->setToolTip(tr("A ball the detector found in a frame without a mark; marked frames use the mark"));
    useDirection_->setObjectName(QStringLiteral("ballModelDirection"));
    useDirection_->setEnabled(false);
    useDirection_->setToolTip(tr("Offered when the ball looks bigger on one side of the mirror: r(d) scaled by "
                                 "1 + a cos(angle) + b sin(angle) (ball.direction_cos, ball.direction_sin)"));
    fitButton_->setObjectName(QStringLiteral("ballModelFit"));
    applyButton_->setObjectName(QStringLiteral("ballModelApply"));
    applyButton_->setToolTip(tr("Write the coefficients c0, c1, c2 into the config (one undo step)"));
    auto* layout = new QVBoxLayout(this);
    auto* help = new QLabel(tr("The ball's radius as seen over its image distance from the mirror centre. Mark balls at "
                               "near and far distances (Truth > Mark ground truth); each mark is a sample."),
                            this);
    help->setWordWrap(true);
    layout->addWidget(help);
    layout->addWidget(plot_, 1);
    layout->addWidget(status_);
    layout->addWidget(useDetections_);
    layout->addWidget(useDirection_);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(fitButton_);
    buttons->addWidget(applyButton_);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    connect(fitButton_, &QPushButton::clicked, this, &BallModelPanel::fit);
    connect(applyButton_, &QPushButton::clicked, this, [this] { emit message(apply().text); });
    connect(useDetections_, &QCheckBox::toggled, this, &BallModelPanel::refresh);
    connect(useDirection_, &QCheckBox::toggled, this, [this] {
        if (fit_) showFit();
    });
    connect(truth_, &TruthDocument::changed, this, &BallModelPanel::refresh);
    refresh();
}

void BallModelPanel::setDetections(std::vector<FrameOutcome> outcomes)
{
    detections_ = std::move(outcomes);
    refresh();
}

std::vector<BallSample> BallModelPanel::samples() const
{
    const GeometryOptions& g = doc_->config().geometry;
    const cv::Point2d centre(g.centerX, g.centerY);
    std::vector<BallSample> s = ballSamplesFromTruth(truth_->rows(), centre);
    if (useDetections_->isChecked()) {
        const auto more = ballSamplesFromDetections(detections_, centre, truth_->rows());
        s.insert(s.end(), more.begin(), more.end());
    }
    return s;
}

void BallModelPanel::refresh()
{
    fit_.reset();
    fitted_ = samples();
    CurveFitPlotData d;
    for (const BallSample& s : fitted_) d.samples.emplace_back(s.distancePx, s.radiusPx);
    d.xName = tr("distance from the centre");
    d.xUnit = d.yUnit = d.residualUnit = QStringLiteral("px");
    d.empty = tr("No samples yet: mark balls (Truth > Mark ground truth) or run the whole session");
    plot_->setPlot(std::move(d));
    status_->setText(tr("%1 sample(s); Fit shows the curve and its residuals").arg(fitted_.size()));
    const QSignalBlocker block(useDirection_);
    useDirection_->setChecked(false);
    useDirection_->setEnabled(false);
}

bool BallModelPanel::fit()
{
    refresh();
    const BallModelFitResult r = fitBallModel(fitted_);
    if (!r.ok()) {
        status_->setText(tr("No fit: %1").arg(QString::fromStdString(r.error->message)));
        return false;
    }
    fit_ = r.fit;
    {
        const QSignalBlocker block(useDirection_);
        useDirection_->setEnabled(fit_->directionOffered);
        useDirection_->setChecked(fit_->directionOffered);
    }
    showFit();
    return true;
}

void BallModelPanel::showFit()
{
    const BallModelFit f = *fit_;
    const bool direction = useDirection_->isChecked() && f.direction;
    CurveFitPlotData d = plot_->plotData();
    if (direction) {
        const BallModelFit::Direction dir = *f.direction;
        d.residuals = dir.residualsPx;
        d.curve = [dir](double x) { return dir.c0 + dir.c1 * x + dir.c2 * x * x; };  // the mean over directions
        d.summary = tr("with direction: RMS %1 px (%2 without)").arg(dir.rmsPx, 0, 'f', 2).arg(f.rmsPx, 0, 'f', 2);
    } else {
        d.residuals = f.residualsPx;
        d.curve = [f](double x) { return f.radiusAt(x); };
        d.summary = tr("fit: RMS %1 px, largest %2 px").arg(f.rmsPx, 0, 'f', 2).arg(f.maxAbsPx, 0, 'f', 2);
    }
    d.curveFrom = f.minDistancePx;
    d.curveTo = f.maxDistancePx;
    plot_->setPlot(std::move(d));
    QString text = tr("r(d) = %1 + %2 d + %3 d^2 from %4 samples over %5..%6 px; RMS %7 px")
                       .arg(f.c0, 0, 'g', 4).arg(f.c1, 0, 'g', 4).arg(f.c2, 0, 'g', 4).arg(fitted_.size())
                       .arg(f.minDistancePx, 0, 'f', 0).arg(f.maxDistancePx, 0, 'f', 0).arg(f.rmsPx, 0, 'f', 2);
    if (!f.directionNote.empty()) text += QStringLiteral("\n") + QString::fromStdString(f.directionNote);
    status_->setText(text);
}

SetupStepOutcome BallModelPanel::apply()
{
    if (!fit_ && !fit()) return {false, status_->text()};
    Config next = doc_->config();
    const bool direction = useDirection_->isChecked() && fit_->direction;
    applyBallModelFit(*fit_, next.ball, direction);
    if (const auto refused = doc_->replaceConfig(next, tr("Fit ball model")))
        return {false, tr("The ball model was refused: %1").arg(*refused)};
    return {true, tr("ball model from %1 samples, RMS %2 px%3")
                      .arg(fitted_.size())
                      .arg(direction ? fit_->direction->rmsPx : fit_->rmsPx, 0, 'f', 2)
                      .arg(direction ? tr(", with the per-direction term") : QString())};
}

QString BallModelPanel::status() const { return status_->text(); }

}  // namespace omnitune
