#include "widgets/CameraSetup.h"

#include "calib/config/ProvisionalGeometry.h"
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
    BusyCursor busy;
    auto opened = openFrameSource(sourcePath_.toStdString());
    if (!opened.ok()) {
        report(tr("Cannot read %1: %2").arg(sourcePath_, QString::fromStdString(opened.error)), false);
        return;
    }
    // Read once: the rim averages them, the body and the mask need the field to move between them.
    FitFrames frames = readFitFrames(*opened.source, frameCount);
    if (!frames.ok()) {
        report(tr("No frames for the fit: %1").arg(QString::fromStdString(frames.error->toString())), false);
        return;
    }
    const MirrorFitResult mirror = fitMirror(frames.images, doc_->config());
    if (!mirror.ok()) {
        report(tr("The mirror rim was not found: %1").arg(QString::fromStdString(mirror.error->toString())), false);
        return;
    }
    if (const auto why = doc_->replaceConfig(mirror.config, tr("Set up: mirror centre, rim and robot body"))) {
        report(tr("The fitted geometry was refused: %1").arg(*why), false);
        return;
    }
    const RimFit& r = mirror.rim;
    const GeometryOptions& g = mirror.config.geometry;
    QStringList lines = toLines(mirror.adapted);
    lines << tr("centre (%1, %2) px, mirror rim %3 px (residual RMS %4 px over %5 deg), outer radius %6 px")
                 .arg(r.centre.x, 0, 'f', 1).arg(r.centre.y, 0, 'f', 1).arg(r.rimRadius, 0, 'f', 1)
                 .arg(r.rmsPx, 0, 'f', 2).arg(r.coverageDeg, 0, 'f', 0).arg(g.outerRadius, 0, 'f', 1);
    lines << tr("robot body: inner radius %1 px").arg(g.innerRadius, 0, 'f', 1);

    const AutoMaskResult mask = autoMask(frames.images, g, ColorLut(mirror.config.colors));
    QString maskText;
    if (mask.ok()) {
        Config withMask = doc_->config();
        withMask.mask = mask.fit.mask;
        if (withMask.geometry.maskFile.empty()) withMask.geometry.maskFile = "mask.png";
        if (const auto why = doc_->replaceConfig(withMask, tr("Set up: robot mask")))
            maskText = tr("mask refused: %1").arg(*why);
        else
            maskText = tr("mask: %1 region(s) that stay put while the field moves, %2 % of the mirror image (saved as "
                          "%3 beside the config)")
                           .arg(mask.fit.regions).arg(100.0 * mask.fit.robotShare, 0, 'f', 1)
                           .arg(QString::fromStdString(withMask.geometry.maskFile));
    } else {
        maskText = tr("no mask proposed: %1").arg(QString::fromStdString(mask.error->toString()));
    }
    lines << maskText;
    notices_->add(tr("Camera set up from %1 frame(s) (each step is one Ctrl+Z):").arg(frames.images.size()), lines);
    report(tr("Camera set up: centre, rim, robot body%1. Next: mark balls (Truth > Mark ground truth) and fit the ball "
              "model, measure the distance map (omnitune-calibrate ball-model / distance-map, docs/calibration.md), then "
              "save (Ctrl+S).")
               .arg(mask.ok() ? tr(" and mask") : QString()),
           true);
}

void CameraSetup::report(const QString& text, bool ok) { bar_->showMessage(text, false, !ok); }

}  // namespace omnitune
