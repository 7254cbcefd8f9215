#include "serve/frame_encoder.h"

#include <algorithm>

#include "core/log.h"
#include "core/parallel.h"
#include "serve/jpeg_encoder.h"

namespace penumbra::serve {
namespace {

using Clock = std::chrono::steady_clock;

// Strips of whole 16-row blocks (a 4:2:0 JPEG's unit), as even as that allows.
std::vector<Strip> stripLayout(std::uint32_t height, int count) {
    const std::uint32_t blocks = (height + 15) / 16;
    const std::uint32_t n = std::clamp<std::uint32_t>(std::uint32_t(count), 1, std::max(1u, blocks));
    std::vector<Strip> strips(n);
    std::uint32_t y = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t end = std::min(height, (blocks * (i + 1) / n) * 16);
        strips[i].y = std::uint16_t(y);
        strips[i].rows = std::uint16_t(end - y);
        y = end;
    }
    return strips;
}

}  // namespace

struct FrameEncoder::Workers {
    // The arena takes no more threads than the machine runs at once (TBB warns of more); the
    // strips stay as many as asked, so the pictures are the same on any machine.
    explicit Workers(int threads)
        : arena(std::min(unsigned(threads), hardwareThreads())), encoders(std::size_t(threads)) {}
    ThreadArena arena;
    std::vector<JpegEncoder> encoders;  // one per strip slot; a strip index picks its encoder
};

FrameEncoder::FrameEncoder(FrameReadback& readback, const EncodeOptions& options, Deliver deliver)
    : readback_(readback), options_(options), deliver_(std::move(deliver)),
      workers_(std::make_unique<Workers>(std::max(1, options.threads))) {
    thread_ = std::thread([this] { run(); });
}

FrameEncoder::~FrameEncoder() {
    stop_ = true;
    readback_.notify();
    thread_.join();
}

void FrameEncoder::run() {
    while (ReadbackSlot* slot = readback_.take(stop_)) {
        std::shared_ptr<EncodedFrame> frame;
        try {
            frame = encode(*slot);
        } catch (const std::exception& e) {
            logWarning(std::string("frame not sent: ") + e.what());
        }
        readback_.release(slot);
        if (frame) deliver_(std::move(frame));
    }
}

std::shared_ptr<EncodedFrame> FrameEncoder::encode(const ReadbackSlot& slot) {
    const FrameMeta& meta = slot.meta;
    const int quality = meta.moving ? options_.motionQuality : options_.restQuality;
    std::vector<Strip> strips = stripLayout(meta.height, int(workers_->encoders.size()));
    std::vector<double> ms(strips.size());
    const auto* pixels = static_cast<const std::uint8_t*>(slot.pixels.mapped());
    workers_->arena.run([&] {
        parallelChunks(strips.size(), 1, [&](std::size_t i, std::size_t, std::size_t) {
            const auto start = Clock::now();
            Strip& s = strips[i];
            workers_->encoders[i].encode(pixels + std::size_t(s.y) * meta.width * 4, int(meta.width), s.rows,
                                         quality, s.jpeg);
            ms[i] = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        });
    });
    auto frame = std::make_shared<EncodedFrame>();
    frame->info.frame = meta.frame;
    frame->info.width = std::uint16_t(meta.width);
    frame->info.height = std::uint16_t(meta.height);
    frame->info.renderMs = meta.renderMs;
    frame->info.encodeMs = float(*std::max_element(ms.begin(), ms.end()));
    frame->info.quality = std::uint32_t(quality);
    frame->stripCount = std::uint32_t(strips.size());
    frame->strips = packStrips(strips);
    frame->acks = meta.acks;
    frame->encodedAt = Clock::now();
    lastEncodeMs_ = frame->info.encodeMs;
    return frame;
}

}  // namespace penumbra::serve
