#include "apps/progress_bar.h"

#include <cstdio>

namespace raylab {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : m_label(std::move(label)), m_enabled(enabled),
      m_start(std::chrono::steady_clock::now()), m_lastDraw(m_start) {}

void ProgressBar::update(double fraction) {
    if (!m_enabled) return;
    const auto now = std::chrono::steady_clock::now();
    if (m_drawn && fraction < 1.0 && now - m_lastDraw < std::chrono::milliseconds(100)) return;
    m_lastDraw = now;
    m_drawn = true;
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth + 0.5);
    std::string bar(size_t(filled), '#');
    bar.append(size_t(kWidth - filled), '.');
    std::fprintf(stderr, "\r%s [%s] %3d%%  ETA %5.1fs ", m_label.c_str(), bar.c_str(),
                 int(fraction * 100.0 + 0.5), eta);
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (!m_enabled || !m_drawn) return;
    std::fprintf(stderr, "\r%*s\r", int(m_label.size()) + 56, "");
    std::fflush(stderr);
}

}  // namespace raylab
