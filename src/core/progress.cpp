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
constexpr auto kJsonInterval = std::chrono::milliseconds(500);
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
    ProgressState state;
    state.done = done;
    state.total = total;
    state.elapsedSeconds = elapsedSeconds;
    return formatProgress(label, state, width);
}

namespace {

// The ETA the state gives, or the rate's estimate; negative when there is none yet.
double etaOf(const ProgressState& s, std::uint64_t done) {
    if (s.etaSeconds >= 0) return s.etaSeconds;
    // No estimate before the first unit is done: it would be a division by zero or a wild guess.
    if (done == 0) return -1;
    return s.elapsedSeconds * static_cast<double>(s.total - done) / static_cast<double>(done);
}

}  // namespace

std::string formatProgress(const std::string& label, const ProgressState& s, int width) {
    const std::uint64_t done = std::min(s.done, s.total);
    const std::uint64_t total = s.total;
    double fraction = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
    std::string eta = formatDuration(etaOf(s, done));
    std::string unit = s.unit.empty() ? "" : " " + s.unit;
    char stats[160];
    std::snprintf(stats, sizeof stats, " %3d%%  %llu/%llu%s  %s elapsed  ETA %s",
                  static_cast<int>(fraction * 100.0), static_cast<unsigned long long>(done),
                  static_cast<unsigned long long>(total), unit.c_str(), formatDuration(s.elapsedSeconds).c_str(),
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

std::string formatProgressJson(const std::string& label, const ProgressState& s, bool final) {
    // Labels and units are ours (plain words), so no escaping beyond refusing quotes is needed.
    auto word = [](std::string w) {
        w.erase(std::remove_if(w.begin(), w.end(), [](char c) { return c == '"' || c == '\\' || c < 32; }), w.end());
        return w;
    };
    const double eta = final ? 0.0 : etaOf(s, std::min(s.done, s.total));
    char etaText[32] = "null";
    if (eta >= 0) std::snprintf(etaText, sizeof etaText, "%.3f", eta);
    char buf[384];
    std::snprintf(buf, sizeof buf,
                  "{\"progress\":\"%s\",\"done\":%llu,\"total\":%llu,\"unit\":\"%s\",\"elapsed\":%.3f,\"eta\":%s,"
                  "\"final\":%s}",
                  word(label).c_str(), static_cast<unsigned long long>(s.done),
                  static_cast<unsigned long long>(s.total), word(s.unit).c_str(), s.elapsedSeconds, etaText,
                  final ? "true" : "false");
    return buf;
}

ProgressBar::ProgressBar(std::string label, std::uint64_t total, bool enabled)
    : ProgressBar(std::move(label), total, enabled ? ProgressMode::Bar : ProgressMode::Off) {}

ProgressBar::ProgressBar(std::string label, std::uint64_t total, ProgressMode mode, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      mode_(mode == ProgressMode::Bar && !::isatty(STDERR_FILENO) ? ProgressMode::Off : mode),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    if (mode_ == ProgressMode::Bar && drawn_) std::fputc('\n', stderr);
}

void ProgressBar::update(std::uint64_t done, double etaSeconds) {
    done_ = done;
    eta_ = etaSeconds;
    if (mode_ == ProgressMode::Off) return;
    auto now = std::chrono::steady_clock::now();
    // Scripts get fewer lines than people get redraws.
    const auto interval = mode_ == ProgressMode::Json ? kJsonInterval : kRedrawInterval;
    if (drawn_ && now - lastDraw_ < interval) return;
    lastDraw_ = now;
    draw(false);
}

void ProgressBar::finish() {
    if (mode_ == ProgressMode::Off) return;
    draw(true);
    if (mode_ == ProgressMode::Bar) std::fputc('\n', stderr);
    mode_ = ProgressMode::Off;
}

ProgressState ProgressBar::state() const {
    ProgressState s;
    s.done = done_;
    s.total = total_;
    s.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    s.etaSeconds = eta_;
    s.unit = unit_;
    return s;
}

void ProgressBar::draw(bool final) {
    if (mode_ == ProgressMode::Json) {
        std::printf("%s\n", formatProgressJson(label_, state(), final).c_str());
        std::fflush(stdout);
        drawn_ = true;
        return;
    }
    // One column short of the terminal: writing into the last column makes some terminals wrap.
    std::string line = formatProgress(label_, state(), terminalWidth() - 1);
    // "\x1b[K" clears what a longer previous line left to the right.
    std::fprintf(stderr, "\r%s\x1b[K", line.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

}  // namespace penumbra
