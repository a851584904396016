#pragma once
// Session > Apply to whole session (Ctrl+R): the current and the saved config over every frame
// of the open source, in the background. Its panel (SessionSweepPanel) is a tab of the window's
// docks from the first run on; when a run ends the slider marks the frames with a ball and
// those where the change made one appear or vanish, and the ball model takes the detections as
// samples. From the first edit, save or truth mark after a run (or during one) its numbers and
// marks say they are outdated: they describe an older pair of configs.
#include <QObject>
#include <QPointer>

#include <memory>

class QString;

namespace omnitune {

class BallModelPanel;
class ConfigDocument;
class FrameNavigator;
class SessionSweepPanel;
struct SweepResult;
class TruthDocument;
class WindowDocks;

class WholeSessionRun : public QObject {
    Q_OBJECT
public:
    WholeSessionRun(ConfigDocument* doc, TruthDocument* truth, FrameNavigator* nav, BallModelPanel* ballModel,
                    WindowDocks* docks, QObject* parent);
    // Stops a run still going (its thread) while what it reports to still exists.
    ~WholeSessionRun() override;

    // Runs over `sourcePath`, which the run opens again in a thread of its own.
    void start(const QString& sourcePath);
    // Another source is open: the results belong to the previous one.
    void reset();
    SessionSweepPanel* panel() const;  // null before the first run

signals:
    void rerunRequested();                  // the panel's Re-run (the window knows the source)
    void finished(const QString& summary);  // for the status bar
    void failed(const QString& why);        // for the notice bar

private:
    void onFinished(std::shared_ptr<const SweepResult> result);

    ConfigDocument* doc_;
    TruthDocument* truth_;
    FrameNavigator* nav_;
    BallModelPanel* ballModel_;
    WindowDocks* docks_;
    QPointer<SessionSweepPanel> panel_;  // made on the first run; its dock owns it
};

}  // namespace omnitune
