// The frame navigator (widgets/FrameNavigator), a real widget offscreen: on a recording its play
// timer ticks frames at the playback speed; in live mode (a camera) play / pause is live /
// paused, it ticks no frame of its own (the camera's grab timer brings them), the speed box is
// disabled, and steps still ask for frames; leaving live mode leaves it paused and playing
// ticks frames again.
#include "widgets/FrameNavigator.h"

#include <QComboBox>
#include <QSignalSpy>
#include <QtTest>

using namespace omnitune;

class FrameNavigatorTest : public QObject {
    Q_OBJECT
private slots:
    void recordingPlaysOnItsOwnTimer()
    {
        FrameNavigator nav;
        nav.setFrameCount(5);
        nav.setFrameRate(100);
        QSignalSpy frames(&nav, &FrameNavigator::frameRequested);
        QSignalSpy playing(&nav, &FrameNavigator::playingChanged);
        nav.togglePlay();
        QVERIFY(nav.isPlaying());
        QVERIFY(nav.isTicking());
        QCOMPARE(playing.count(), 1);
        QVERIFY(frames.wait(2000));  // the timer's first tick
        QCOMPARE(frames.first().first().toInt(), 1);
        nav.togglePlay();
        QVERIFY(!nav.isPlaying());
        QVERIFY(!nav.isTicking());
    }

    void liveModeTicksNothingOfItsOwn()
    {
        FrameNavigator nav;
        nav.setFrameCount(5);
        nav.setFrameRate(100);
        nav.togglePlay();  // a recording playing when the camera opens
        QSignalSpy playing(&nav, &FrameNavigator::playingChanged);
        nav.setLive(true);
        QVERIFY(nav.isLive());
        QVERIFY(!nav.isPlaying());  // paused first: the recording's owner is told
        QCOMPARE(playing.count(), 1);
        QCOMPARE(playing.last().first().toBool(), false);
        auto* speed = nav.findChild<QComboBox*>();
        QVERIFY(speed && !speed->isEnabled());  // the camera's rate, not a playback speed

        QSignalSpy frames(&nav, &FrameNavigator::frameRequested);
        nav.togglePlay();  // live
        QVERIFY(nav.isPlaying());
        QCOMPARE(playing.last().first().toBool(), true);
        QVERIFY(!nav.isTicking());
        nav.setFrameRate(100);  // a config change while live starts no timer either
        QVERIFY(!nav.isTicking());
        QVERIFY(frames.isEmpty());
        // A step (slider, arrows) still asks for its frame: the controller pauses there.
        nav.next();
        QCOMPARE(frames.count(), 1);

        // The camera closes: paused, and a recording plays on the navigator's timer again.
        nav.setLive(false);
        QVERIFY(!nav.isLive());
        QVERIFY(!nav.isPlaying());
        QCOMPARE(playing.last().first().toBool(), false);
        QVERIFY(speed->isEnabled());
        nav.togglePlay();
        QVERIFY(nav.isTicking());
        QVERIFY(frames.wait(2000));
        QCOMPARE(frames.count(), 2);
    }
};

QTEST_MAIN(FrameNavigatorTest)
#include "widgets_frame_navigator_test.moc"
