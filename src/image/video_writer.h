// H.264 video files (.mp4, .mkv, .mov) through FFmpeg's libraries (Debian libavcodec-dev,
// libavformat-dev, libswscale-dev): display-ready sRGB frames in, one frame at a time, converted
// to YUV 4:2:0 (BT.709, limited range, as players expect) and encoded by libx264.
// The writer writes the file it is given; callers that must never leave a half-written video
// hand it a PendingFile's temporary path (core/atomic_file.h) and commit after finish().
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>

namespace penumbra {

// Whether the path names a video container by its extension (.mp4, .mkv, .mov; any case).
bool isVideoPath(const std::filesystem::path& path);

struct VideoSettings {
    std::uint32_t width = 0, height = 0;  // even: 4:2:0 halves both (UsageError otherwise)
    double fps = 24;
    // x264's constant rate factor: 0 lossless, 18 visually lossless, 23 its default. Path-traced
    // noise costs bits, so a little better than the default.
    int crf = 18;
};

class VideoWriter {
public:
    // file: where the bytes go; container: a path whose extension names the format (the target
    // itself when `file` is a temporary name). Error when the file cannot be opened or this
    // FFmpeg has no H.264 encoder.
    VideoWriter(const std::filesystem::path& file, const std::filesystem::path& container,
                const VideoSettings& settings);
    ~VideoWriter();
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    // One frame: RGB8, row-major, top row first, width * height * 3 bytes.
    void addFrame(std::span<const std::uint8_t> rgb);
    // Flushes the encoder's delayed frames and writes the container's index. Call once, last.
    void finish();
    std::uint64_t frames() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace penumbra
