#include "widgets/CameraSetup.h"

#include "calib/config/ProvisionalGeometry.h"
#include "calib/fit/BodyFit.h"
#include "calib/fit/FitFrames.h"
#include "calib/fit/MirrorFit.h"
#include "calib/mask/AutoMask.h"
#include "calib/source/FrameSourceFactory.h"
#include "core/ColorLut.h"
#include "widgets/CameraSetupBar.h"
#include "widgets/ConfigDocument.h"
#include "widgets/ConfigFiles.h"
#include "widgets/NoticeBar.h"

#include <QApplication>
#include <QFileInfo>

#include <algorithm>

namespace omnitune {

namespace {

QString sizeText(cv::Size s) { return QStringLiteral("%1x%2").arg(s.width).arg(s.height); }

QStringList toLines(const std::vector<std::string>& lines)
{
    QStringList out;
    for (const auto& l : lines) out << QString::fromStdString(l);
    return out;
}

// A wait cursor for the length of a fit (a second or two on the GUI thread).
struct BusyCursor {
    BusyCursor() { QApplication::setOverrideCursor(Qt::WaitCursor); }
    ~BusyCursor() { QApplication::restoreOverrideCursor(); }
};

}  // namespace

CameraSetup::CameraSetup(ConfigDocument* doc, const ConfigFiles* files, NoticeBar* notices, CameraSetupBar* bar,
                         QObject* parent)
    : QObject(parent), doc_(doc), files_(files), notices_(notices), bar_(bar)
{
    connect(bar_, &CameraSetupBar::adaptRequested, this, &CameraSetup::adapt);
    connect(bar_, &CameraSetupBar::setUpRequested, this, &CameraSetup::setUp);
}

void CameraSetup::setSource(const QString& path)
{
    sourcePath_ = path;
    frames_.clear();
    rimRadius_ = 0.0;
    frameSize_ = {};
    offered_ = false;
    bar_->hide();
}

void CameraSetup::frameSizeMismatch(cv::Size frameSize)
{
    if (offered_ && frameSize == frameSize_) return;  // one offer per source, not one per frame
    frameSize_ = frameSize;
    offered_ = true;
    const auto& g = doc_->config().geometry;
    if (files_->showsBuiltInDefaults() && !doc_->isDirty()) {
        // The built-in defaults: nothing of the user's is replaced, so the frames show at once.
        adapt();
        return;
    }
    const QString name = doc_->path().isEmpty() ? tr("The config") : QFileInfo(doc_->path()).fileName();
    bar_->showMessage(tr("These frames are %1, but %2 is for %3 frames: nothing is processed until the geometry fits "
                         "this camera. Adapt it (a first guess, scaled to the frames), or set the camera up from its frames.")
                          .arg(sizeText(frameSize), name, sizeText({g.imageWidth, g.imageHeight})),
                      true, true);
}

void CameraSetup::adapt()
{
    if (frameSize_.empty()) return;
    const ProvisionalGeometry p = provisionalGeometry(doc_->config(), frameSize_);
    if (const auto why = doc_->replaceConfig(p.config, tr("Adapt to %1 frames").arg(sizeText(frameSize_)))) {
        report(tr("The config could not be adapted: %1").arg(*why), false);
        return;
    }
    notices_->add(tr("Provisional geometry for %1 frames (Ctrl+Z undoes):").arg(sizeText(frameSize_)), toLines(p.changes));
    bar_->showMessage(tr("A provisional geometry for these %1 frames is in use: the mirror as the largest circle in "
                         "the frame. Set the camera up to find its real centre, rim, robot body and mask.")
                          .arg(sizeText(frameSize_)),
                      false, true);
}

void CameraSetup::setUp()
{
    if (sourcePath_.isEmpty()) return;
    bar_->hide();  // the sequence's strip takes over
    emit sequenceRequested();
}

const std::vector<cv::Mat>& CameraSetup::frames(QString* why)
{
    if (!frames_.empty()) return frames_;
    auto opened = openFrameSource(sourcePath_.toStdString());
    if (!opened.ok()) {
        *why = tr("Cannot read %1: %2").arg(sourcePath_, QString::fromStdString(opened.error));
        return frames_;
    }
    // Read once: the rim averages them, the body and the mask need the field to move between them.
    FitFrames read = readFitFrames(*opened.source, frameCount);
    if (!read.ok())
        *why = tr("No frames for the fit: %1").arg(QString::fromStdString(read.error->toString()));
    else
        frames_ = std::move(read.images);
    return frames_;
}

SetupStepOutcome CameraSetup::fitCentreAndRim()
{
    BusyCursor busy;
    QString why;
    const auto& images = frames(&why);
    if (images.empty()) return {false, why};
    const MirrorFitResult mirror = fitMirror(images, doc_->config(), {}, false);
    if (!mirror.ok())
        return {false, tr("The mirror rim was not found: %1").arg(QString::fromStdString(mirror.error->toString()))};
    if (const auto refused = doc_->replaceConfig(mirror.config, tr("Set up: mirror centre and rim")))
        return {false, tr("The fitted geometry was refused: %1").arg(*refused)};
    rimRadius_ = mirror.rim.rimRadius;
    const RimFit& r = mirror.rim;
    QStringList lines = toLines(mirror.adapted);
    lines << tr("centre (%1, %2) px, mirror rim %3 px (residual RMS %4 px over %5 deg), outer radius %6 px")
                 .arg(r.centre.x, 0, 'f', 1).arg(r.centre.y, 0, 'f', 1).arg(r.rimRadius, 0, 'f', 1)
                 .arg(r.rmsPx, 0, 'f', 2).arg(r.coverageDeg, 0, 'f', 0).arg(mirror.config.geometry.outerRadius, 0, 'f', 1);
    notices_->add(tr("Centre and rim from %1 frame(s) (Ctrl+Z undoes):").arg(images.size()), lines);
    return {true, lines.back()};
}

SetupStepOutcome CameraSetup::fitRobotBody()
{
    BusyCursor busy;
    QString why;
    const auto& images = frames(&why);
    if (images.empty()) return {false, why};
    Config next = doc_->config();
    GeometryOptions& g = next.geometry;
    const double rim = rimRadius_ > 0 ? rimRadius_ : g.outerRadius;
    const BodyFitResult body = fitBody(images, {g.centerX, g.centerY}, rim);
    if (!body.ok())
        return {false, tr("The robot body was not found: %1").arg(QString::fromStdString(body.error->toString()))};
    g.innerRadius = std::min(body.fit.innerRadius, 0.9 * g.outerRadius);  // never an empty ring
    if (const auto refused = doc_->replaceConfig(next, tr("Set up: robot body")))
        return {false, tr("The inner radius was refused: %1").arg(*refused)};
    return {true, tr("robot body: inner radius %1 px").arg(g.innerRadius, 0, 'f', 1)};
}

SetupStepOutcome CameraSetup::proposeMask()
{
    BusyCursor busy;
    QString why;
    const auto& images = frames(&why);
    if (images.empty()) return {false, why};
    const Config& now = doc_->config();
    const AutoMaskResult mask = autoMask(images, now.geometry, ColorLut(now.colors));
    if (!mask.ok()) return {false, tr("No mask proposed: %1").arg(QString::fromStdString(mask.error->toString()))};
    Config withMask = now;
    withMask.mask = mask.fit.mask;
    if (withMask.geometry.maskFile.empty()) withMask.geometry.maskFile = "mask.png";
    if (const auto refused = doc_->replaceConfig(withMask, tr("Set up: robot mask")))
        return {false, tr("The mask was refused: %1").arg(*refused)};
    return {true, tr("mask: %1 region(s) that stay put while the field moves, %2 % of the mirror image (saved as "
                     "%3 beside the config)")
                      .arg(mask.fit.regions).arg(100.0 * mask.fit.robotShare, 0, 'f', 1)
                      .arg(QString::fromStdString(withMask.geometry.maskFile))};
}

void CameraSetup::report(const QString& text, bool ok) { bar_->showMessage(text, false, !ok); }

}  // namespace omnitune
