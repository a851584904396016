#pragma once
// Setting up a camera the config does not fit yet, from the window (issue 11). When frames of
// another size than the config's arrive, the window either adapts at once (the config is the
// built-in defaults, never loaded or saved, so nothing of the user's is replaced) or asks, through the yellow
// CameraSetupBar. "Set up this camera" then starts the guided sequence (SetupSequence), whose
// first steps call the fits here: the mirror centre and rim, the robot body (calib/fit/) and a
// proposed mask (calib/mask/AutoMask), from frames of the open source read once; each step is
// one undo command on the window's stack. The fits themselves live in calib/; this class only
// reads frames and hands results to the ConfigDocument.
#include <opencv2/core.hpp>

#include <QObject>
#include <QString>
#include <QStringList>

#include <vector>

class QWidget;

namespace omnitune {

class CameraSetupBar;
class ConfigDocument;
class ConfigFiles;
class NoticeBar;

// What one step of the set-up did: `ok` false changed nothing, and `text` says why.
struct SetupStepOutcome {
    bool ok = false;
    QString text;
};

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

    // The steps of the sequence that fit from frames; each applies one undo command, or
    // changes nothing and says why. The rim step keeps the inner radius; the body step uses the
    // centre and rim on screen (fitted or dragged).
    SetupStepOutcome fitCentreAndRim();
    SetupStepOutcome fitRobotBody();
    SetupStepOutcome proposeMask();

public slots:
    // Provisional geometry for the frames' size (calib/config/ProvisionalGeometry.h).
    void adapt();
    // Starts the guided sequence (sequenceRequested); the bar steps aside for it.
    void setUp();

signals:
    void sequenceRequested();

private:
    // The step's result on the bar; `ok` false keeps "Set up this camera" offered to retry.
    void report(const QString& text, bool ok);
    // Frames of the source, read once per source; empty with `why` set when none could be read.
    const std::vector<cv::Mat>& frames(QString* why);

    ConfigDocument* doc_;
    const ConfigFiles* files_;
    NoticeBar* notices_;
    CameraSetupBar* bar_;
    QString sourcePath_;
    cv::Size frameSize_;
    bool offered_ = false;  // the bar was shown for this source already
    std::vector<cv::Mat> frames_;
    double rimRadius_ = 0.0;  // px, of the last rim fit; 0: none yet (the outer radius stands in)
};

}  // namespace omnitune
