// serve-probe: watches a `penumbra serve` with N headless clients for a while and prints what
// they got as JSON (frames per second, bytes per frame, Mbit/s, input-to-frame latency, the
// server's GPU and encoding times) and, given --pid, the server's resident memory over the run.
//
//   serve-probe --port 8080 [--clients 8] [--seconds 60] [--pid PID] [--save DIR --save-count 4]
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <thread>

#include "serve/probe/probe_client.h"

namespace {

using penumbra::serve::probe::ProbeOptions;
using penumbra::serve::probe::ProbeResult;

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

nlohmann::json summary(const ProbeResult& r) {
    const double seconds = std::max(r.seconds, 1e-9);
    return {{"frames", r.frames},
            {"fps", double(r.frames) / seconds},
            {"bytesPerFrame", r.frames ? double(r.bytes) / double(r.frames) : 0.0},
            {"mbits", double(r.bytes) * 8 / seconds / 1e6},
            {"latencyMsMedian", percentile(r.latencyMs, 0.5)},
            {"latencyMsP95", percentile(r.latencyMs, 0.95)},
            {"latencySamples", r.latencyMs.size()},
            {"renderMsMedian", percentile(r.renderMs, 0.5)},
            {"encodeMsMedian", percentile(r.encodeMs, 0.5)},
            {"encodeMsP95", percentile(r.encodeMs, 0.95)},
            {"encodeMsMax", percentile(r.encodeMs, 1.0)},
            {"width", r.width},
            {"height", r.height},
            {"quality", r.lastQuality},
            {"lastStats", nlohmann::json::parse(r.lastStats, nullptr, false)},
            {"error", r.error}};
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"serve-probe: headless clients of penumbra serve"};
    ProbeOptions o;
    int clients = 1, pid = 0;
    bool noAck = false;
    app.add_option("--host", o.host, "server address (default 127.0.0.1)");
    app.add_option("--port", o.port, "server port")->required();
    app.add_option("--token", o.target, "")->each([&](const std::string& t) { o.target = "/ws?token=" + t; });
    app.add_option("--clients", clients, "clients at once (default 1)")->check(CLI::Range(1, 64));
    app.add_option("--seconds", o.seconds, "how long to watch (default 10)")->check(CLI::Range(0.1, 3600.0));
    app.add_option("--input-every", o.inputEvery, "seconds between timed inputs (default 0.25; 0: none)");
    app.add_flag("--no-ack", noAck, "never acknowledge frames (a browser that stopped drawing)");
    app.add_option("--pid", pid, "the server's process id: sample its resident memory each second");
    app.add_option("--save", o.saveDir, "write a few received frames as PNG into this folder");
    app.add_option("--save-count", o.saveCount, "how many (default 4 when --save is given)");
    CLI11_PARSE(app, argc, argv);
    o.ackFrames = !noAck;
    if (!o.saveDir.empty() && o.saveCount == 0) o.saveCount = 4;

    std::atomic<bool> stop{false};
    std::vector<ProbeResult> results(static_cast<std::size_t>(clients));
    std::vector<std::thread> threads;
    for (int i = 0; i < clients; ++i)
        threads.emplace_back([&, i] {
            ProbeOptions mine = o;
            if (i > 0) mine.saveDir.clear();  // the first client's frames stand for all
            results[std::size_t(i)] = penumbra::serve::probe::runProbe(mine, stop);
        });
    std::vector<long> rss;
    for (double t = 0; pid > 0 && t < o.seconds; t += 1) {
        rss.push_back(penumbra::serve::probe::residentKiB(pid));
        std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    for (auto& t : threads) t.join();

    nlohmann::json out = {{"clients", nlohmann::json::array()}};
    bool ok = true;
    for (const ProbeResult& r : results) {
        out["clients"].push_back(summary(r));
        ok = ok && r.error.empty() && r.frames > 0;
    }
    if (!rss.empty()) out["serverRssKiB"] = rss;
    std::printf("%s\n", out.dump(2).c_str());
    return ok ? 0 : 1;
}
