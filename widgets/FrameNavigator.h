#pragma once
// Frame-by-frame control of a recorded source: first / previous / play / next / last, a slider,
// a frame number box, loop and playback speed. It asks for frames (frameRequested); the
// window decides what showing one means. The slider carries marks (FrameMark.h): where a
// ball was detected, where a config change made one appear or vanish. In live mode (a camera,
// LiveController) play / pause means live / paused and the navigator ticks no frames of its
// own: the camera's grab timer brings them; the speed box, which does not apply, is disabled.
#include "widgets/FrameMark.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;
class QTimer;
class QToolButton;

namespace omnitune {

class MarkedSlider;

class FrameNavigator : public QWidget {
    Q_OBJECT
public:
    explicit FrameNavigator(QWidget* parent = nullptr);

    void setFrameCount(int count);
    void setFrameRate(double fps);
    int frameCount() const { return count_; }
    int current() const { return current_; }
    bool isPlaying() const { return playing_; }
    // Live mode on or off; either way it starts paused (the caller plays when it wants).
    void setLive(bool on);
    bool isLive() const { return live_; }
    // Whether the navigator's own play timer runs (playing a recording; never while live).
    bool isTicking() const;

    // Slider marks (MarkedSlider): each owner replaces or sets only its own kinds. A new frame
    // count clears them all: they belonged to the previous source.
    void setMarks(const QVector<FrameMark>& marks, const QVector<FrameMarkKind>& kinds);
    void setMark(int frame, FrameMarkKind kind, bool on);
    void setMarksOutdated(const QVector<FrameMarkKind>& kinds);
    MarkedSlider* slider() const { return slider_; }

public slots:
    void setCurrent(int index);  // shows `index` as current; emits nothing
    void goTo(int index);        // clamps (or wraps when looping) and requests the frame
    void next();
    void previous();
    void first();
    void last();
    void togglePlay();

signals:
    void frameRequested(int index);
    void playingChanged(bool playing);  // play / pause toggled (the live view follows it)

private:
    void updateLabels();
    void updatePlayButton();

    int count_ = 0;
    int current_ = 0;
    double fps_ = 30.0;
    bool playing_ = false;
    bool live_ = false;
    QToolButton* firstButton_;
    QToolButton* previousButton_;
    QToolButton* playButton_;
    QToolButton* nextButton_;
    QToolButton* lastButton_;
    MarkedSlider* slider_;
    QSpinBox* frameBox_;
    QLabel* countLabel_;
    QCheckBox* loop_;
    QComboBox* speed_;
    QTimer* timer_;
};

}  // namespace omnitune
