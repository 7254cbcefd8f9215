// One watching browser, without a browser: connects to `penumbra serve`'s WebSocket, reads frames
// and acknowledges them as a page does, sends an input now and then to time input-to-frame
// latency, and keeps the figures. For scripts/gpu-serve-bench.sh and the load test.
#pragma once

#include <atomic>
#include <chrono>
#include <string>
#include <vector>

namespace penumbra::serve::probe {

struct ProbeOptions {
    std::string host = "127.0.0.1";
    std::string port = "8080";
    std::string target = "/ws";  // with ?token=... when the server has one
    double seconds = 10;
    double inputEvery = 0.25;   // seconds between look inputs (0: none)
    bool ackFrames = true;      // false: a browser that never draws (the slow-client test)
    std::string saveDir;        // where to write frames as PNG ("" : none)
    int saveCount = 0;
};

struct ProbeResult {
    std::uint64_t frames = 0, bytes = 0, texts = 0;
    double seconds = 0;
    std::vector<double> latencyMs;  // input sent -> first frame whose ack covers it
    std::vector<double> renderMs, encodeMs;
    std::uint32_t width = 0, height = 0;
    std::uint32_t lastQuality = 0;
    std::string hello, lastStats;  // the server's text messages (JSON), the first and the latest
    std::string error;  // "" : ran to the end
};

ProbeResult runProbe(const ProbeOptions& options, const std::atomic<bool>& stop);

// A process's resident memory in KiB, from /proc (0 when it cannot be read): the server's, watched
// by the load test and the GPU benchmark.
long residentKiB(int pid);

}  // namespace penumbra::serve::probe
