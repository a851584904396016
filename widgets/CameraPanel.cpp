#include "widgets/CameraPanel.h"

#include "calib/camera/CameraSettingsIo.h"
#include "widgets/CalibrationPlot.h"
#include "widgets/IntensityHistogramView.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace omnitune {

namespace {

QString label(CameraFeatureId id)
{
    switch (id) {
    case CameraFeatureId::Exposure: return CameraPanel::tr("Exposure");
    case CameraFeatureId::Shutter: return CameraPanel::tr("Shutter");
    case CameraFeatureId::Gain: return CameraPanel::tr("Gain");
    case CameraFeatureId::Brightness: return CameraPanel::tr("Brightness");
    case CameraFeatureId::WhiteBalanceBlue: return CameraPanel::tr("White balance U/B");
    case CameraFeatureId::WhiteBalanceRed: return CameraPanel::tr("White balance V/R");
    case CameraFeatureId::Gamma: return CameraPanel::tr("Gamma");
    case CameraFeatureId::Saturation: return CameraPanel::tr("Saturation");
    }
    return {};
}

const char* const kProblemStyle = "color: #b00020;";
const char* const kGoodStyle = "color: #1b7a2e;";

}  // namespace

CameraPanel::CameraPanel(QWidget* parent) : QWidget(parent)
{
    // Rows, histogram and plots are taller than a laptop's dock: they scroll.
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* content = new QWidget(scroll);
    scroll->setWidget(content);
    outer->addWidget(scroll);
    auto* layout = new QVBoxLayout(content);
    rowsBox_ = new QWidget(this);
    layout->addWidget(rowsBox_);
    auto* autoRow = new QHBoxLayout;
    allAutoOff_ = new QPushButton(tr("All camera auto modes off"), this);
    allAutoOff_->setToolTip(tr("Turns off every automatic mode of the camera, so the image does not drift during a match"));
    autoRow->addWidget(allAutoOff_);
    autoState_ = new QLabel(this);
    autoState_->setWordWrap(true);
    autoRow->addWidget(autoState_, 1);
    layout->addLayout(autoRow);

    auto* live = new QGroupBox(tr("Live intensity histogram"), this);
    auto* liveLayout = new QVBoxLayout(live);
    histogram_ = new IntensityHistogramView(live);
    msv_ = new QLabel(tr("No frame yet"), live);
    msv_->setWordWrap(true);
    msv_->setMinimumHeight(2 * msv_->fontMetrics().lineSpacing());  // both lines, also when squeezed
    msv_->setToolTip(tr("MSV over the pixels the detector uses; U and V of the white reference region "
                        "(neutral at camera_auto.chroma_target); grey level of the black reference region"));
    liveLayout->addWidget(histogram_);
    liveLayout->addWidget(msv_);
    layout->addWidget(live);
    auto* buttons = new QHBoxLayout;
    start_ = new QPushButton(tr("Auto-calibrate"), this);
    start_->setToolTip(tr("Exposure, gain, white balance and brightness by the thesis' ref. [31] (camera_auto.* in the config)"));
    stop_ = new QPushButton(tr("Stop"), this);
    revert_ = new QPushButton(tr("Revert"), this);
    revert_->setToolTip(tr("Back to the settings from before the calibration"));
    buttons->addWidget(start_);
    buttons->addWidget(stop_);
    buttons->addWidget(revert_);
    layout->addLayout(buttons);
    status_ = new QLabel(this);
    status_->setWordWrap(true);
    layout->addWidget(status_);
    auto* convergence = new QGroupBox(tr("Calibration convergence"), this);
    auto* convergenceLayout = new QVBoxLayout(convergence);
    plot_ = new CalibrationPlot(convergence);
    convergenceLayout->addWidget(plot_);
    layout->addWidget(convergence, 1);
    connect(this, &CameraPanel::calibrationIteration, plot_, &CalibrationPlot::addIteration);

    connect(allAutoOff_, &QPushButton::clicked, this, &CameraPanel::allAutoOff);
    connect(start_, &QPushButton::clicked, this, &CameraPanel::startCalibration);
    connect(stop_, &QPushButton::clicked, this, [this] { stopCalibration(tr("Calibration stopped")); });
    connect(revert_, &QPushButton::clicked, this, &CameraPanel::revertCalibration);
    stepTimer_.setInterval(0);
    connect(&stepTimer_, &QTimer::timeout, this, &CameraPanel::stepCalibration);
    rebuild();
}

CameraPanel::~CameraPanel() = default;

void CameraPanel::setCamera(Camera* camera, const CameraAutoOptions& options, const cv::Mat& usedMask)
{
    stepTimer_.stop();
    calibration_.reset();
    camera_ = camera;
    options_ = options;
    usedMask_ = usedMask;
    histogram_->clear();
    histogramClock_.invalidate();
    msv_->setText(tr("No frame yet"));
    msv_->setStyleSheet(QString());
    plot_->setTargets(options_);
    rebuild();
    setStatus(camera_ ? QString::fromStdString(camera_->description()) : tr("No camera"), false);
}

void CameraPanel::setOptions(const CameraAutoOptions& options, const cv::Mat& usedMask)
{
    options_ = options;
    usedMask_ = usedMask;
    histogramClock_.invalidate();  // the next frame shows the change
}

void CameraPanel::showFrame(const cv::Mat& bgr)
{
    if (bgr.empty() || bgr.type() != CV_8UC3 || !isVisible()) return;
    if (histogramClock_.isValid() && histogramClock_.elapsed() < histogramIntervalMs_) return;
    histogramClock_.start();
    // A geometry made for another frame size cannot select pixels: count them all, and say so.
    const bool maskFits = usedMask_.empty() || usedMask_.size() == bgr.size();
    CameraMeasurement m;
    if (const auto why = measureCameraFrame(bgr, maskFits ? usedMask_ : cv::Mat(), options_, m)) {
        histogram_->clear();
        msv_->setText(tr("No measurement: %1").arg(QString::fromStdString(*why)));
        msv_->setStyleSheet(kProblemStyle);
        return;
    }
    histogram_->setHistogram(m.histogram, m.msv, options_.msvTarget, options_.msvTolerance);
    const bool onTarget = std::abs(m.msv - options_.msvTarget) <= options_.msvTolerance;
    QString text = tr("MSV %1 (target %2 \u00b1 %3)\nwhite region U %4 V %5, black region %6")
                       .arg(m.msv, 0, 'f', 2)
                       .arg(options_.msvTarget, 0, 'f', 2)
                       .arg(options_.msvTolerance, 0, 'f', 2)
                       .arg(m.u, 0, 'f', 1)
                       .arg(m.v, 0, 'f', 1)
                       .arg(m.black, 0, 'f', 1);
    if (!maskFits)
        text += tr(" (whole frame: the geometry is for %1x%2 frames)").arg(usedMask_.cols).arg(usedMask_.rows);
    msv_->setText(text);
    msv_->setStyleSheet(onTarget ? kGoodStyle : QString());
}

QString CameraPanel::msvText() const { return msv_->text(); }

void CameraPanel::rebuild()
{
    delete rowsBox_->layout();
    qDeleteAll(rowsBox_->findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly));
    rows_.clear();
    auto* grid = new QGridLayout(rowsBox_);
    grid->setContentsMargins(0, 0, 0, 0);
    int r = 0;
    for (const CameraFeature& f : camera_ ? camera_->features() : std::vector<CameraFeature>{}) {
        Row row;
        row.slider = new QSlider(Qt::Horizontal, rowsBox_);
        row.spin = new QSpinBox(rowsBox_);
        row.slider->setRange(f.min, f.max);
        row.spin->setRange(f.min, f.max);
        row.spin->setKeyboardTracking(false);  // one write on Enter, not one per digit typed
        row.slider->setValue(f.value);
        row.spin->setValue(f.value);
        row.spin->setToolTip(tr("%1 .. %2, the camera's register units").arg(f.min).arg(f.max));
        row.automatic = new QCheckBox(tr("auto"), rowsBox_);
        row.automatic->setEnabled(f.autoCapable);
        row.automatic->setChecked(f.autoOn);
        if (!f.autoCapable) row.automatic->setToolTip(tr("This camera has no automatic mode for it"));
        row.mismatch = new QLabel(rowsBox_);
        row.mismatch->setStyleSheet(kProblemStyle);
        grid->addWidget(new QLabel(label(f.id), rowsBox_), r, 0);
        grid->addWidget(row.slider, r, 1);
        grid->addWidget(row.spin, r, 2);
        grid->addWidget(row.automatic, r, 3);
        grid->addWidget(row.mismatch, r, 4);
        const CameraFeatureId id = f.id;
        connect(row.slider, &QSlider::valueChanged, row.spin, &QSpinBox::setValue);
        connect(row.spin, QOverload<int>::of(&QSpinBox::valueChanged), this, [this, id](int v) {
            if (!refreshing_) write(id, v);
        });
        connect(row.automatic, &QCheckBox::toggled, this, [this, id](bool on) {
            if (!refreshing_) setAuto(id, on);
        });
        rows_[id] = row;
        ++r;
    }
    grid->setColumnStretch(1, 1);
    updateButtons();
    updateAutoState();
}

void CameraPanel::refresh()
{
    if (!camera_) return;
    refreshing_ = true;
    for (const CameraFeature& f : camera_->features()) {
        const auto it = rows_.find(f.id);
        if (it == rows_.end()) continue;
        const QSignalBlocker b1(it->second.slider);
        it->second.slider->setValue(f.value);
        it->second.spin->setValue(f.value);
        it->second.automatic->setChecked(f.autoOn);
    }
    refreshing_ = false;
    updateAutoState();
}

void CameraPanel::write(CameraFeatureId id, int value)
{
    if (!camera_) return;
    std::string mismatch;
    QLabel* beside = rows_[id].mismatch;
    beside->clear();
    if (const auto err = setAndCheckFeature(*camera_, id, value, mismatch)) {
        setStatus(QString::fromStdString(err->message), true);
        beside->setText(tr("not written"));
        beside->setToolTip(QString::fromStdString(err->message));
    } else if (!mismatch.empty()) {
        setStatus(QString::fromStdString(mismatch), true);
        beside->setText(tr("asked for %1").arg(value));  // the spin box shows what the camera holds
        beside->setToolTip(QString::fromStdString(mismatch));
    } else {
        setStatus(QString::fromStdString(std::string(cameraFeatureName(id)) + " " + std::to_string(value)), false);
    }
    {
        const QSignalBlocker b(rows_[id].slider);
        rows_[id].slider->setValue(value);
    }
    refresh();
}

void CameraPanel::setAuto(CameraFeatureId id, bool on)
{
    if (!camera_) return;
    if (const auto err = camera_->setAuto(id, on)) setStatus(QString::fromStdString(err->message), true);
    refresh();
}

void CameraPanel::allAutoOff()
{
    if (!camera_) return;
    int turnedOff = 0;
    for (const CameraFeature& f : camera_->features())
        if (f.autoOn) {
            if (const auto err = camera_->setAuto(f.id, false)) {
                setStatus(QString::fromStdString(err->message), true);
                refresh();
                return;
            }
            ++turnedOff;
        }
    setStatus(turnedOff ? tr("%n automatic mode(s) turned off", nullptr, turnedOff) : tr("No automatic mode was on"), false);
    refresh();
}

void CameraPanel::startCalibration()
{
    if (!camera_) return;
    calibration_ = std::make_unique<CameraAutoCalibration>(*camera_, options_, usedMask_);
    if (const auto err = calibration_->begin()) {
        setStatus(QString::fromStdString(err->message), true);
        return;
    }
    if (calibration_->state() != CameraAutoState::Running) {
        setStatus(tr("not converged: %1").arg(QString::fromStdString(calibration_->reason())), true);
        return;
    }
    setStatus(tr("Calibrating..."), false);
    plot_->setTargets(options_);  // and no points: each run plots from its first iteration
    stepTimer_.start();
    updateButtons();
    emit calibrationStarted();
}

void CameraPanel::stepCalibration()
{
    if (!calibration_ || !camera_) return stepTimer_.stop();
    Frame frame;
    std::optional<CameraError> err = grabber_ ? grabber_(frame) : camera_->grab(frame);
    if (!calibration_) return;  // the grab's fault took the camera away (setCamera(nullptr))
    CameraAutoIteration it;
    bool measured = false;
    if (err)
        calibration_->abort(err->message);
    else
        err = calibration_->take(frame, it, measured);
    if (!measured && calibration_->state() == CameraAutoState::Running && !err) return;  // skipped: next turn
    if (it.iteration > 0) {
        emit calibrationIteration(it.iteration, it.measured.msv, it.measured.u, it.measured.v, it.measured.black);
        setStatus(tr("iteration %1: %2").arg(it.iteration).arg(QString::fromStdString(formatCameraMeasurement(it.measured))),
                  false);
    }
    refresh();
    if (calibration_->state() == CameraAutoState::Running && !err) return;
    stepTimer_.stop();
    const bool converged = calibration_->state() == CameraAutoState::Converged;
    const QString text = converged ? tr("converged: %1 iterations=%2")
                                         .arg(QString::fromStdString(formatCameraMeasurement(it.measured)))
                                         .arg(calibration_->iterations())
                                   : tr("not converged: %1").arg(QString::fromStdString(calibration_->reason()));
    setStatus(text, !converged);
    updateButtons();
    emit calibrationFinished(converged, text);
}

void CameraPanel::stopCalibration(const QString& why)
{
    stepTimer_.stop();
    setStatus(why, false);
    updateButtons();
}

void CameraPanel::revertCalibration()
{
    if (!calibration_) return;
    stepTimer_.stop();
    if (const auto err = calibration_->revert())
        setStatus(QString::fromStdString(err->message), true);
    else
        setStatus(tr("Settings from before the calibration restored"), false);
    refresh();
    updateButtons();
}

void CameraPanel::setStatus(const QString& text, bool problem)
{
    status_->setText(text);
    status_->setStyleSheet(problem ? kProblemStyle : QString());
}

QString CameraPanel::statusText() const { return status_->text(); }

QString CameraPanel::mismatchText(CameraFeatureId id) const
{
    const auto it = rows_.find(id);
    return it == rows_.end() ? QString() : it->second.mismatch->text();
}

QString CameraPanel::autoStateText() const { return autoState_->text(); }

void CameraPanel::updateAutoState()
{
    QStringList on;
    for (const auto& [id, row] : rows_)
        if (row.automatic->isChecked()) on << label(id).toLower();
    if (!camera_)
        autoState_->clear();
    else if (on.isEmpty())
        autoState_->setText(tr("Camera auto modes: all off (the image holds still)"));
    else
        autoState_->setText(tr("Camera auto modes ON: %1 (the image may drift)").arg(on.join(", ")));
    autoState_->setStyleSheet(!camera_ ? QString() : on.isEmpty() ? kGoodStyle : kProblemStyle);
}

void CameraPanel::updateButtons()
{
    const bool running = stepTimer_.isActive();
    allAutoOff_->setEnabled(camera_ && !running);
    start_->setEnabled(camera_ && !running);
    stop_->setEnabled(running);
    revert_->setEnabled(calibration_ != nullptr && !running);
}

QSpinBox* CameraPanel::spinBox(CameraFeatureId id) const
{
    const auto it = rows_.find(id);
    return it == rows_.end() ? nullptr : it->second.spin;
}

QSlider* CameraPanel::slider(CameraFeatureId id) const
{
    const auto it = rows_.find(id);
    return it == rows_.end() ? nullptr : it->second.slider;
}

QCheckBox* CameraPanel::autoBox(CameraFeatureId id) const
{
    const auto it = rows_.find(id);
    return it == rows_.end() ? nullptr : it->second.automatic;
}

}  // namespace omnitune
