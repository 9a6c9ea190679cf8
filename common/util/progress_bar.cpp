#include "util/progress_bar.h"

#include "util/clock.h"

#include <fmt/core.h>

#include <algorithm>
#include <unistd.h>

namespace tp {

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)), enabled_(isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    if (drawn_) fmt::print(stderr, "\n");
}

void ProgressBar::update(double fraction) {
    update(fraction, "");
}

void ProgressBar::update(double fraction, const std::string& note) {
    if (!enabled_) return;
    fraction = std::clamp(fraction, 0.0, 1.0);
    const double elapsed = seconds_since(start_);
    const int width = 30, filled = int(fraction * width + 0.5);
    const std::string eta =
        fraction > 0 ? fmt::format("{:.0f}s left", elapsed * (1 - fraction) / fraction) : "";
    fmt::print(stderr, "\r{} [{}{}] {:3.0f}% {:.1f}s {}{}   ", label_, std::string(filled, '#'),
               std::string(width - filled, '.'), 100 * fraction, elapsed, eta,
               note.empty() ? "" : " (" + note + ")");
    std::fflush(stderr);
    drawn_ = true;
}

std::function<void(double)> ProgressBar::callback() {
    if (!enabled_) return {};
    return [this](double f) { update(f); };
}

} // namespace tp
