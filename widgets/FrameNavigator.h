#pragma once
// Frame-by-frame control of a recorded source: first / previous / play / next / last, a slider,
// a frame number box, loop and playback speed. It asks for frames (frameRequested); the
// window decides what showing one means.
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;
class QTimer;
class QToolButton;

namespace omnitune {

class FrameNavigator : public QWidget {
    Q_OBJECT
public:
    explicit FrameNavigator(QWidget* parent = nullptr);

    void setFrameCount(int count);
    void setFrameRate(double fps);
    int frameCount() const { return count_; }
    int current() const { return current_; }
    bool isPlaying() const;

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

private:
    void updateLabels();

    int count_ = 0;
    int current_ = 0;
    double fps_ = 30.0;
    QToolButton* firstButton_;
    QToolButton* previousButton_;
    QToolButton* playButton_;
    QToolButton* nextButton_;
    QToolButton* lastButton_;
    QSlider* slider_;
    QSpinBox* frameBox_;
    QLabel* countLabel_;
    QCheckBox* loop_;
    QComboBox* speed_;
    QTimer* timer_;
};

}  // namespace omnitune
