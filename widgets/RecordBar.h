#pragma once
// The strip under the panes while the live view records (Camera > Record): the folder, the
// time since the start, frames written, frames dropped and the disk's free space, refreshed a
// few times a second from the recorder, and a Stop button. Hidden when nothing records.
#include <QElapsedTimer>
#include <QFrame>
#include <QTimer>

class QLabel;
class QPushButton;

namespace omnitune {

class CameraRecorder;

class RecordBar : public QFrame {
    Q_OBJECT
public:
    explicit RecordBar(QWidget* parent = nullptr);

    // Shows `recorder`'s progress (it must outlive the bar's use of it: set null before it goes).
    void setRecorder(CameraRecorder* recorder);
    QString text() const;
    QPushButton* stopButton() const { return stop_; }

signals:
    void stopRequested();
    // The recorder stopped by itself (the disk nearly full, a write failed): `why`.
    void stoppedByItself(const QString& why);

private:
    void refresh();

    CameraRecorder* recorder_ = nullptr;
    QLabel* label_;
    QPushButton* stop_;
    QTimer timer_;
    QElapsedTimer elapsed_;
};

}  // namespace omnitune
