#pragma once
// The last seconds of a live camera, kept to step through after a pause (as SSL-Vision's DVR
// does): a ring of frames, each with a sequence number that never repeats, the oldest dropped
// when the ring is full, so memory stays bounded. Positions count from the oldest frame
// (0 .. size()-1) and move while frames come in; sequence numbers do not. Shared between the
// GUI thread, which pushes, and the pipeline's thread, which reads (ReplaySource): every call
// locks.
#include "calib/source/Frame.h"

#include <deque>
#include <mutex>

namespace omnitune {

class ReplayBuffer {
public:
    // At least one frame.
    explicit ReplayBuffer(int capacity);
    // Frames that `seconds` hold at `frameRate` (config camera.replay_seconds, camera.frame_rate).
    static int capacityFor(double seconds, double frameRate);

    int capacity() const { return capacity_; }
    int size() const;
    // Adds `frame` as the newest, dropping the oldest when full; its sequence number.
    int push(const Frame& frame);
    void clear();  // sequence numbers go on from where they were

    // The frame with sequence number `seq` (its index set to `seq`); false when it has left
    // the ring or never came.
    bool find(int seq, Frame& out) const;
    // Sequence number at `position` (0: the oldest); -1 outside 0..size()-1.
    int seqAt(int position) const;
    // Position of `seq`; -1 when it is not in the ring.
    int positionOf(int seq) const;
    // Newest sequence number; -1 when empty.
    int newestSeq() const;
    // `position` moved by `delta` frames, held inside the ring (a step past either end stays
    // at that end); -1 when empty.
    int step(int position, int delta) const;

private:
    struct Entry {
        int seq;
        Frame frame;
    };
    const int capacity_;
    mutable std::mutex mutex_;
    std::deque<Entry> ring_;
    int nextSeq_ = 0;
};

}  // namespace omnitune
