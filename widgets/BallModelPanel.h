#pragma once
// The ball model from the window (issue 11): samples of the ball as seen (its image distance
// from the mirror centre and its radius) from the session's ground-truth marks and, when a
// whole-session run found balls, from its accepted detections; the fit r(d) (calib/fit/
// BallModelFit, the same as omnitune-calibrate ball-model) with the samples and residuals in
// a plot and the RMS in px; Apply writes the coefficients as one undo step. A fit that cannot
// be made (too few samples, too short a span) says why and changes nothing. When the residuals
// depend on the ball's direction (an off-axis mirror), the per-direction term is offered: the
// box is enabled and ticked, the plot shows the residuals with it, Apply writes it too.
#include "calib/eval/Evaluation.h"
#include "calib/fit/BallModelFit.h"
#include "widgets/CameraSetup.h"

#include <QWidget>

#include <optional>
#include <vector>

class QCheckBox;
class QLabel;
class QPushButton;

namespace omnitune {

class ConfigDocument;
class CurveFitPlot;
class TruthDocument;

class BallModelPanel : public QWidget {
    Q_OBJECT
public:
    BallModelPanel(ConfigDocument* doc, const TruthDocument* truth, QWidget* parent = nullptr);

    // The detections of the latest whole-session run (replacing earlier ones); empty: none.
    void setDetections(std::vector<FrameOutcome> outcomes);
    // The samples as they would be fitted now (truth marks, then detections when included).
    std::vector<BallSample> samples() const;
    // Fits and shows the result; false (with the reason) when no fit can be made.
    bool fit();
    // Writes the shown fit as one undo step; fits first when nothing is shown.
    SetupStepOutcome apply();

    CurveFitPlot* plot() const { return plot_; }
    QString status() const;
    const std::optional<BallModelFit>& lastFit() const { return fit_; }
    QCheckBox* directionBox() const { return useDirection_; }

signals:
    void message(const QString& text);  // for the status bar

private:
    void refresh();   // the samples without a fit, after the truth or the detections changed
    void showFit();   // fit_ on the plot and in the status, with or without the direction term

    ConfigDocument* doc_;
    const TruthDocument* truth_;
    std::vector<FrameOutcome> detections_;
    std::optional<BallModelFit> fit_;
    std::vector<BallSample> fitted_;  // the samples of fit_
    CurveFitPlot* plot_;
    QLabel* status_;
    QCheckBox* useDetections_;
    QCheckBox* useDirection_;
    QPushButton* fitButton_;
    QPushButton* applyButton_;
};

}  // namespace omnitune
