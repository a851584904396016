// The live view's replay buffer (calib/camera/ReplayBuffer) and its FrameSource
// (ReplaySource): capacity from seconds and frame rate, the oldest dropped when full (memory
// bounded), sequence numbers that never repeat, positions that move with the ring, stepping
// held inside the ring, and a frame that has left it read as a clear OutOfRange error.
#include "calib/camera/ReplayBuffer.h"
#include "calib/camera/ReplaySource.h"

#include <QtTest>

using namespace omnitune;

namespace {
Frame frameOf(int value)
{
    Frame f;
    f.image = cv::Mat(4, 6, CV_8UC3, cv::Scalar::all(value));
    f.index = value;  // the camera's own index: the buffer numbers frames itself
    return f;
}
int valueOf(const Frame& f) { return f.image.at<cv::Vec3b>(0, 0)[0]; }
}  // namespace

class ReplayBufferTest : public QObject {
    Q_OBJECT
private slots:
    void capacityFollowsSecondsAndFrameRate()
    {
        QCOMPARE(ReplayBuffer::capacityFor(10.0, 30.0), 300);
        QCOMPARE(ReplayBuffer::capacityFor(0.5, 15.0), 8);  // rounded
        QCOMPARE(ReplayBuffer::capacityFor(0.0, 30.0), 1);  // never empty
        QCOMPARE(ReplayBuffer(0).capacity(), 1);
    }

    void dropsTheOldestWhenFull()
    {
        ReplayBuffer ring(3);
        for (int v = 10; v < 15; ++v) QCOMPARE(ring.push(frameOf(v)), v - 10);  // numbers 0..4
        QCOMPARE(ring.size(), 3);  // bounded
        QCOMPARE(ring.seqAt(0), 2);  // 0 and 1 are gone
        QCOMPARE(ring.newestSeq(), 4);
        Frame f;
        QVERIFY(!ring.find(1, f));
        QVERIFY(ring.find(2, f));
        QCOMPARE(valueOf(f), 12);
        QCOMPARE(f.index, 2);  // the sequence number, not the camera's index
        QVERIFY(ring.find(4, f));
        QCOMPARE(valueOf(f), 14);
        QVERIFY(!ring.find(5, f));  // not yet
    }

    void positionsMoveSequenceNumbersStay()
    {
        ReplayBuffer ring(4);
        for (int v = 0; v < 4; ++v) ring.push(frameOf(v));
        QCOMPARE(ring.positionOf(3), 3);
        ring.push(frameOf(4));
        QCOMPARE(ring.positionOf(3), 2);  // one older now
        QCOMPARE(ring.positionOf(0), -1);
        QCOMPARE(ring.seqAt(4), -1);
        QCOMPARE(ring.seqAt(-1), -1);
        ring.clear();
        QCOMPARE(ring.size(), 0);
        QCOMPARE(ring.push(frameOf(9)), 5);  // numbers go on after a clear
    }

    void steppingStaysInsideTheRing()
    {
        ReplayBuffer ring(5);
        QCOMPARE(ring.step(0, -1), -1);  // empty
        for (int v = 0; v < 7; ++v) ring.push(frameOf(v));  // holds 2..6
        int p = ring.size() - 1;  // newest
        p = ring.step(p, -1);
        p = ring.step(p, -1);
        QCOMPARE(ring.seqAt(p), 4);  // two back
        p = ring.step(p, +1);
        QCOMPARE(ring.seqAt(p), 5);  // one forward
        QCOMPARE(ring.step(p, +10), 4);  // held at the newest
        QCOMPARE(ring.step(p, -10), 0);  // held at the oldest
        QCOMPARE(ring.seqAt(ring.step(7, 0)), 6);  // a place past the end reads as the newest
    }

    void replaySourceReadsBySequenceNumber()
    {
        auto ring = std::make_shared<ReplayBuffer>(2);
        ReplaySource source(ring, "simulated camera", cv::Size(6, 4));
        for (int v = 20; v < 23; ++v) ring->push(frameOf(v));  // holds numbers 1 and 2
        QVERIFY(source.isSeekable());
        QCOMPARE(source.frameSize(), cv::Size(6, 4));
        Frame f;
        QVERIFY(!source.read(2, f));
        QCOMPARE(valueOf(f), 22);
        QVERIFY(!source.read(1, f));
        QCOMPARE(valueOf(f), 21);
        const auto err = source.read(0, f);
        QVERIFY(err);
        QCOMPARE(err->kind, FrameErrorKind::OutOfRange);
        QVERIFY2(QString::fromStdString(err->message).contains("left the replay buffer"), err->message.c_str());
    }
};

QTEST_GUILESS_MAIN(ReplayBufferTest)
#include "calib_replay_buffer_test.moc"
