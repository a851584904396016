#include "calib/camera/ReplayBuffer.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

ReplayBuffer::ReplayBuffer(int capacity) : capacity_(std::max(capacity, 1)) {}

int ReplayBuffer::capacityFor(double seconds, double frameRate)
{
    return std::max(1, int(std::lround(std::max(seconds, 0.0) * std::max(frameRate, 0.0))));
}

int ReplayBuffer::size() const
{
    std::lock_guard<std::mutex> lock(mutex_);
    return int(ring_.size());
}

int ReplayBuffer::push(const Frame& frame)
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (int(ring_.size()) >= capacity_) ring_.pop_front();
    ring_.push_back({nextSeq_, frame});
    return nextSeq_++;
}

void ReplayBuffer::clear()
{
    std::lock_guard<std::mutex> lock(mutex_);
    ring_.clear();
}

bool ReplayBuffer::find(int seq, Frame& out) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (ring_.empty() || seq < ring_.front().seq || seq > ring_.back().seq) return false;
    out = ring_[std::size_t(seq - ring_.front().seq)].frame;  // numbers in the ring are consecutive
    out.index = seq;
    return true;
}

int ReplayBuffer::seqAt(int position) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (position < 0 || position >= int(ring_.size())) return -1;
    return ring_[std::size_t(position)].seq;
}

int ReplayBuffer::positionOf(int seq) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (ring_.empty() || seq < ring_.front().seq || seq > ring_.back().seq) return -1;
    return seq - ring_.front().seq;
}

int ReplayBuffer::newestSeq() const
{
    std::lock_guard<std::mutex> lock(mutex_);
    return ring_.empty() ? -1 : ring_.back().seq;
}

int ReplayBuffer::step(int position, int delta) const
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (ring_.empty()) return -1;
    return std::clamp(position + delta, 0, int(ring_.size()) - 1);
}

}  // namespace omnitune
