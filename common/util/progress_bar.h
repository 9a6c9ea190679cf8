// A one-line progress bar on stderr, shown only when stderr is a terminal.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace tp {

class ProgressBar {
  public:
    explicit ProgressBar(std::string label);
    ~ProgressBar(); // ends the line if anything was drawn
    void update(double fraction);
    // The same with a note after the bar (each engine's share, when several render at once).
    void update(double fraction, const std::string& note);
    // The callback form RenderOptions::progress takes; empty when stderr is not a terminal.
    std::function<void(double)> callback();

  private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
};

} // namespace tp
