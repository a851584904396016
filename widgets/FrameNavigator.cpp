#include "widgets/FrameNavigator.h"

#include "widgets/MarkedSlider.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>
#include <QToolButton>

namespace omnitune {

namespace {
QToolButton* button(QWidget* parent, QStyle::StandardPixmap icon, const QString& tip)
{
    auto* b = new QToolButton(parent);
    b->setIcon(parent->style()->standardIcon(icon));
    b->setToolTip(tip);
    b->setAutoRaise(true);
    return b;
}
}  // namespace

FrameNavigator::FrameNavigator(QWidget* parent) : QWidget(parent), timer_(new QTimer(this))
{
    firstButton_ = button(this, QStyle::SP_MediaSkipBackward, tr("First frame (Home)"));
    previousButton_ = button(this, QStyle::SP_MediaSeekBackward, tr("Previous frame (Left)"));
    playButton_ = button(this, QStyle::SP_MediaPlay, tr("Play / pause (Space)"));
    nextButton_ = button(this, QStyle::SP_MediaSeekForward, tr("Next frame (Right)"));
    lastButton_ = button(this, QStyle::SP_MediaSkipForward, tr("Last frame (End)"));
    slider_ = new MarkedSlider(this);  // its tooltip names the frame and explains the marks
    frameBox_ = new QSpinBox(this);
    frameBox_->setToolTip(tr("Jump to frame"));
    frameBox_->setKeyboardTracking(false);
    countLabel_ = new QLabel(this);
    loop_ = new QCheckBox(tr("loop"), this);
    loop_->setChecked(true);
    speed_ = new QComboBox(this);
    for (double s : {0.25, 0.5, 1.0, 2.0, 4.0}) speed_->addItem(QStringLiteral("%1x").arg(s), s);
    speed_->setCurrentIndex(2);
    speed_->setToolTip(tr("Playback speed relative to the recording's frame rate"));

    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(4, 2, 4, 2);
    for (QWidget* w : std::initializer_list<QWidget*>{firstButton_, previousButton_, playButton_, nextButton_, lastButton_})
        row->addWidget(w);
    row->addWidget(slider_, 1);
    row->addWidget(frameBox_);
    row->addWidget(countLabel_);
    row->addWidget(loop_);
    row->addWidget(speed_);
    // Clicked transport controls must not keep the keyboard: Space would press the button
    // (or tick "loop") again instead of playing, and arrows would move the slider or speed.
    for (QWidget* w : std::initializer_list<QWidget*>{firstButton_, previousButton_, playButton_, nextButton_,
                                                      lastButton_, slider_, loop_, speed_})
        w->setFocusPolicy(Qt::NoFocus);

    connect(firstButton_, &QToolButton::clicked, this, &FrameNavigator::first);
    connect(previousButton_, &QToolButton::clicked, this, &FrameNavigator::previous);
    connect(playButton_, &QToolButton::clicked, this, &FrameNavigator::togglePlay);
    connect(nextButton_, &QToolButton::clicked, this, &FrameNavigator::next);
    connect(lastButton_, &QToolButton::clicked, this, &FrameNavigator::last);
    connect(slider_, &QSlider::valueChanged, this, &FrameNavigator::goTo);
    connect(frameBox_, qOverload<int>(&QSpinBox::valueChanged), this, &FrameNavigator::goTo);
    connect(speed_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] { setFrameRate(fps_); });
    connect(timer_, &QTimer::timeout, this, [this] {
        if (!loop_->isChecked() && current_ + 1 >= count_) {
            togglePlay();
            return;
        }
        next();
    });
    setFrameCount(0);
}

void FrameNavigator::setFrameCount(int count)
{
    count_ = std::max(count, 0);
    const QSignalBlocker a(slider_);
    const QSignalBlocker b(frameBox_);
    slider_->setRange(0, std::max(count_ - 1, 0));
    slider_->clearMarks();
    frameBox_->setRange(0, std::max(count_ - 1, 0));
    setEnabled(count_ > 0);
    updateLabels();
}

void FrameNavigator::setFrameRate(double fps)
{
    fps_ = fps > 0 ? fps : 30.0;
    timer_->setInterval(int(1000.0 / (fps_ * speed_->currentData().toDouble())));
}

bool FrameNavigator::isTicking() const { return timer_->isActive(); }

void FrameNavigator::setLive(bool on)
{
    if (playing_) togglePlay();  // paused first, so playingChanged tells the old mode's owner
    live_ = on;
    speed_->setEnabled(!on);
    speed_->setToolTip(on ? tr("Live frames come at the camera's own frame rate (camera.frame_rate)")
                          : tr("Playback speed relative to the recording's frame rate"));
    updatePlayButton();
}

void FrameNavigator::setMarks(const QVector<FrameMark>& marks, const QVector<FrameMarkKind>& kinds)
{
    slider_->setMarks(marks, kinds);
}

void FrameNavigator::setMark(int frame, FrameMarkKind kind, bool on) { slider_->setMark(frame, kind, on); }

void FrameNavigator::setMarksOutdated(const QVector<FrameMarkKind>& kinds) { slider_->setOutdated(kinds); }

void FrameNavigator::setCurrent(int index)
{
    current_ = index;
    updateLabels();
}

void FrameNavigator::goTo(int index)
{
    if (count_ <= 0) return;
    if (index >= count_) index = loop_->isChecked() ? 0 : count_ - 1;
    if (index < 0) index = loop_->isChecked() ? count_ - 1 : 0;
    setCurrent(index);
    emit frameRequested(index);
}

void FrameNavigator::next() { goTo(current_ + 1); }
void FrameNavigator::previous() { goTo(current_ - 1); }
void FrameNavigator::first() { goTo(0); }
void FrameNavigator::last() { goTo(count_ - 1); }

void FrameNavigator::togglePlay()
{
    playing_ = !playing_;
    if (playing_ && !live_) {
        setFrameRate(fps_);
        timer_->start();
    } else {
        timer_->stop();
    }
    updatePlayButton();
    emit playingChanged(playing_);
}

void FrameNavigator::updatePlayButton()
{
    playButton_->setIcon(style()->standardIcon(playing_ ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    playButton_->setToolTip(live_ ? tr("Live / pause (Space); paused, the arrows step through the replay buffer")
                                  : tr("Play / pause (Space)"));
}

void FrameNavigator::updateLabels()
{
    const QSignalBlocker a(slider_);
    const QSignalBlocker b(frameBox_);
    slider_->setValue(current_);
    frameBox_->setValue(current_);
    countLabel_->setText(tr("/ %1").arg(std::max(count_ - 1, 0)));  // 0-based, as the frame files
}

}  // namespace omnitune
