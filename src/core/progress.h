// A one-line progress bar on stderr for long renders. It draws only when stderr is a terminal,
// so logs and pipes stay clean, and redraws at most ~10 times a second so it costs nothing.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace penumbra {

// The line without '\r', e.g. "render [=====>    ]  45%  450/1000  0:12 elapsed  ETA 0:15",
// at most width columns (the bar shrinks; below a minimum it is dropped). Pure, for tests.
std::string formatProgress(const std::string& label, std::uint64_t done, std::uint64_t total,
                           double elapsedSeconds, int width);

// "m:ss", or "h:mm:ss" from one hour on.
std::string formatDuration(double seconds);

class ProgressBar {
public:
    // enabled = false (e.g. --quiet) turns it off even on a terminal.
    ProgressBar(std::string label, std::uint64_t total, bool enabled);
    ~ProgressBar();  // ends the line if finish() was not called (e.g. an error unwinds)
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void update(std::uint64_t done);
    void finish();  // draws the last state and ends the line

private:
    void draw();

    std::string label_;
    std::uint64_t total_;
    std::uint64_t done_ = 0;
    bool active_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastDraw_;
};

}  // namespace penumbra
