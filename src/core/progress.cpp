#include "core/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

namespace penumbra {
namespace {

constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
constexpr int kMinBarWidth = 10;

int terminalWidth() {
    winsize ws{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) return ws.ws_col;
    return 80;
}

}  // namespace

std::string formatDuration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0) return "--:--";
    auto s = static_cast<std::uint64_t>(seconds + 0.5);
    char buf[32];
    if (s >= 3600) {
        std::snprintf(buf, sizeof buf, "%llu:%02llu:%02llu",
                      static_cast<unsigned long long>(s / 3600),
                      static_cast<unsigned long long>(s / 60 % 60),
                      static_cast<unsigned long long>(s % 60));
    } else {
        std::snprintf(buf, sizeof buf, "%llu:%02llu", static_cast<unsigned long long>(s / 60),
                      static_cast<unsigned long long>(s % 60));
    }
    return buf;
}

std::string formatProgress(const std::string& label, std::uint64_t done, std::uint64_t total,
                           double elapsedSeconds, int width) {
    done = std::min(done, total);
    double fraction = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
    // No estimate before the first unit is done: it would be a division by zero or a wild guess.
    std::string eta = done == 0 ? "--:--"
                                : formatDuration(elapsedSeconds * static_cast<double>(total - done) /
                                                 static_cast<double>(done));
    char stats[128];
    std::snprintf(stats, sizeof stats, " %3d%%  %llu/%llu  %s elapsed  ETA %s",
                  static_cast<int>(fraction * 100.0), static_cast<unsigned long long>(done),
                  static_cast<unsigned long long>(total), formatDuration(elapsedSeconds).c_str(),
                  eta.c_str());

    std::string line = label;
    // "label [" + bar + "]" + stats
    int barWidth = width - static_cast<int>(label.size() + 3 + std::strlen(stats));
    if (barWidth >= kMinBarWidth) {
        int filled = static_cast<int>(fraction * barWidth);
        line += " [";
        line.append(static_cast<std::size_t>(filled), '=');
        if (filled < barWidth) {
            line += '>';
            line.append(static_cast<std::size_t>(barWidth - filled - 1), ' ');
        }
        line += ']';
    }
    line += stats;
    if (width > 0 && line.size() > static_cast<std::size_t>(width)) line.resize(width);
    return line;
}

ProgressBar::ProgressBar(std::string label, std::uint64_t total, bool enabled)
    : label_(std::move(label)),
      total_(total),
      active_(enabled && ::isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    if (active_ && drawn_) std::fputc('\n', stderr);
}

void ProgressBar::update(std::uint64_t done) {
    done_ = done;
    if (!active_) return;
    auto now = std::chrono::steady_clock::now();
    if (drawn_ && now - lastDraw_ < kRedrawInterval) return;
    lastDraw_ = now;
    draw();
}

void ProgressBar::finish() {
    if (!active_) return;
    draw();
    std::fputc('\n', stderr);
    active_ = false;
}

void ProgressBar::draw() {
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    // One column short of the terminal: writing into the last column makes some terminals wrap.
    std::string line = formatProgress(label_, done_, total_, elapsed, terminalWidth() - 1);
    // "\x1b[K" clears what a longer previous line left to the right.
    std::fprintf(stderr, "\r%s\x1b[K", line.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

}  // namespace penumbra
