#pragma once
// A one-line progress bar with percent and ETA on stderr (terminals only).

#include <chrono>
#include <string>

namespace raylab {

class ProgressBar {
public:
    /// Draws nothing unless `enabled` (the caller checks isatty and --quiet).
    ProgressBar(std::string label, bool enabled);
    /// fraction in [0, 1]; redraws at most ~10 times per second.
    void update(double fraction);
    /// Clears the line.
    void finish();

private:
    std::string m_label;
    bool m_enabled;
    std::chrono::steady_clock::time_point m_start;
    std::chrono::steady_clock::time_point m_lastDraw;
    bool m_drawn = false;
};

}  // namespace raylab
