// Progress of long work: a one-line bar on stderr for people, or JSON lines on stdout for
// scripts (--progress json). The bar draws only when stderr is a terminal, so logs and pipes
// stay clean; both redraw at most a few times a second so they cost nothing.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace penumbra {

// What one progress report says. eta < 0: estimate it from the rate so far.
struct ProgressState {
    std::uint64_t done = 0;
    std::uint64_t total = 0;
    double elapsedSeconds = 0;
    double etaSeconds = -1;
    std::string unit;  // after the counts, e.g. "spp"
};

// The line without '\r', e.g. "render [=====>    ]  45%  450/1000  0:12 elapsed  ETA 0:15",
// at most width columns (the bar shrinks; below a minimum it is dropped). Pure, for tests.
std::string formatProgress(const std::string& label, std::uint64_t done, std::uint64_t total,
                           double elapsedSeconds, int width);
std::string formatProgress(const std::string& label, const ProgressState& state, int width);

// One JSON object on one line, without the newline:
// {"progress":"<label>","done":45,"total":1000,"unit":"spp","elapsed":12.3,"eta":15.2,"final":false}
// eta is null before anything is done. Pure, for tests.
std::string formatProgressJson(const std::string& label, const ProgressState& state, bool final);

// "m:ss", or "h:mm:ss" from one hour on.
std::string formatDuration(double seconds);

enum class ProgressMode { Off, Bar, Json };

class ProgressBar {
public:
    // enabled = false (e.g. --quiet) turns it off even on a terminal.
    ProgressBar(std::string label, std::uint64_t total, bool enabled);
    // Bar: on stderr when it is a terminal. Json: lines on stdout, always.
    ProgressBar(std::string label, std::uint64_t total, ProgressMode mode, std::string unit = "");
    ~ProgressBar();  // ends the line if finish() was not called (e.g. an error unwinds)
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    // etaSeconds >= 0 replaces the estimate from the rate (a time budget ends the work sooner).
    void update(std::uint64_t done, double etaSeconds = -1);
    void finish();  // draws the last state and ends the line

private:
    void draw(bool final);
    ProgressState state() const;

    std::string label_;
    std::string unit_;
    std::uint64_t total_;
    std::uint64_t done_ = 0;
    double eta_ = -1;
    ProgressMode mode_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastDraw_;
};

}  // namespace penumbra
