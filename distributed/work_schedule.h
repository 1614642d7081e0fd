#pragma once
// How rank 0 hands out a frame's work items: guided self-scheduling over a
// scattered item order. Chunks shrink as the queue drains, so ranks that
// finish early keep getting work and the last chunks are single items; the
// scattered order spreads every chunk over the whole frame, so one chunk does
// not land entirely on an expensive region (a glass sphere) while others are cheap.

#include <vector>

namespace raylab {

/// Positions [begin, begin + count) of the hand-out order; count 0 = no more work.
struct WorkChunk {
    int begin = 0;
    int count = 0;
};

/// A permutation of 0..n-1 visiting item i·s mod n, with the stride s the
/// integer nearest n/φ (φ the golden ratio) that is coprime to n: consecutive
/// positions land far apart in the frame, and any run of positions samples
/// the whole frame evenly. Deterministic: every rank computes the same order.
std::vector<int> scatteredOrder(int n);

/// Guided self-scheduling (Polychronopoulos and Kuck, 1987): each chunk takes
/// ceil(remaining / (2·workers)) items, at least one. The factor 2 leaves
/// room for the chunk every worker holds in reserve while it renders one.
class GuidedSchedule {
public:
    /// `items` >= 0 work items shared by `workers` >= 1 ranks.
    GuidedSchedule(int items, int workers);

    /// The next chunk, or {end, 0} once every item was handed out.
    WorkChunk next();
    /// Items not handed out yet.
    int remaining() const { return m_items - m_next; }

private:
    int m_items;
    int m_workers;
    int m_next = 0;
};

}  // namespace raylab
