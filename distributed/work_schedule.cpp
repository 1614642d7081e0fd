#include "distributed/work_schedule.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace raylab {

std::vector<int> scatteredOrder(int n) {
    if (n < 0) throw std::invalid_argument("scatteredOrder: negative item count");
    std::vector<int> order(static_cast<size_t>(n));
    if (n == 0) return order;
    const double invPhi = 0.6180339887498949;  // 1/φ: the most irrational step
    long long stride = std::max(1LL, std::llround(n * invPhi));
    while (std::gcd(stride, (long long)n) != 1) ++stride;  // coprime: a full cycle
    long long p = 0;
    for (int i = 0; i < n; ++i) {
        order[size_t(i)] = int(p);
        p = (p + stride) % n;
    }
    return order;
}

GuidedSchedule::GuidedSchedule(int items, int workers)
    : m_items(std::max(0, items)), m_workers(std::max(1, workers)) {}

WorkChunk GuidedSchedule::next() {
    const int left = remaining();
    if (left <= 0) return {m_items, 0};
    const int share = 2 * m_workers;
    const int count = std::max(1, (left + share - 1) / share);
    const WorkChunk chunk{m_next, count};
    m_next += count;
    return chunk;
}

}  // namespace raylab
