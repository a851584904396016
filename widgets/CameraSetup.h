#pragma once
// Setting up a camera the config does not fit yet, from the window (issue 11). When frames of
// another size than the config's arrive, the window either adapts at once (the config is the
// built-in defaults, never loaded or saved, so nothing of the user's is replaced) or asks, through the yellow
// CameraSetupBar. "Set up this camera" then fits the mirror centre, rim and robot body
// (calib/fit/MirrorFit) and proposes a mask (calib/mask/AutoMask) from frames of the open
// source; each step is one undo command on the window's stack. The fits themselves live in
// calib/; this class only reads frames and hands results to the ConfigDocument.
#include <opencv2/core.hpp>

#include <QObject>
#include <QString>
#include <QStringList>

class QWidget;

namespace omnitune {

class CameraSetupBar;
class ConfigDocument;
class ConfigFiles;
class NoticeBar;

class CameraSetup : public QObject {
    Q_OBJECT
public:
    CameraSetup(ConfigDocument* doc, const ConfigFiles* files, NoticeBar* notices, CameraSetupBar* bar,
                QObject* parent = nullptr);

    // A new source was opened (the fits re-open it by this path in a reader of their own).
    void setSource(const QString& path);
    // A frame of `frameSize` could not be processed because the config is for another size.
    void frameSizeMismatch(cv::Size frameSize);

    int frameCount = 16;  // frames read once for the rim, body and mask fits (tests use fewer)

public slots:
    // Provisional geometry for the frames' size (calib/config/ProvisionalGeometry.h).
    void adapt();
    // Mirror centre, rim and body, then a proposed mask, from frames of the source.
    void setUp();

private:
    // The step's result on the bar; `ok` false keeps "Set up this camera" offered to retry.
    void report(const QString& text, bool ok);

    ConfigDocument* doc_;
    const ConfigFiles* files_;
    NoticeBar* notices_;
    CameraSetupBar* bar_;
    QString sourcePath_;
    cv::Size frameSize_;
    bool offered_ = false;  // the bar was shown for this source already
};

}  // namespace omnitune
