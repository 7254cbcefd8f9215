// Test helper: reads a video file back with FFmpeg's libraries (the same ones the writer uses)
// into RGB8 frames, so tests check what a player would show: the frame count, the size, the
// pixels.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::test {

struct DecodedVideo {
    std::string error;  // empty on success
    std::string codec;  // e.g. "h264"
    int width = 0, height = 0;
    double fps = 0;
    std::vector<std::vector<std::uint8_t>> frames;  // RGB8, width * height * 3 each
};

inline DecodedVideo decodeVideo(const std::filesystem::path& path) {
    DecodedVideo out;
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, path.string().c_str(), nullptr, nullptr) < 0) {
        out.error = "cannot open " + path.string();
        return out;
    }
    AVCodecContext* codec = nullptr;
    AVFrame* frame = av_frame_alloc();
    AVPacket* packet = av_packet_alloc();
    SwsContext* scaler = nullptr;
    auto collect = [&] {
        while (avcodec_receive_frame(codec, frame) >= 0) {
            scaler = sws_getCachedContext(scaler, frame->width, frame->height, AVPixelFormat(frame->format),
                                          frame->width, frame->height, AV_PIX_FMT_RGB24, SWS_POINT, nullptr,
                                          nullptr, nullptr);
            // As a player does: the matrix and range the stream is tagged with.
            const int* matrix = sws_getCoefficients(frame->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT);
            sws_setColorspaceDetails(scaler, matrix, frame->color_range == AVCOL_RANGE_JPEG, matrix, 1, 0, 1 << 16,
                                     1 << 16);
            std::vector<std::uint8_t> rgb(std::size_t(frame->width) * frame->height * 3);
            std::uint8_t* planes[1] = {rgb.data()};
            const int strides[1] = {frame->width * 3};
            sws_scale(scaler, frame->data, frame->linesize, 0, frame->height, planes, strides);
            out.frames.push_back(std::move(rgb));
        }
    };
    int streamIndex = -1;
    if (avformat_find_stream_info(format, nullptr) >= 0)
        streamIndex = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (streamIndex < 0) {
        out.error = "no video stream in " + path.string();
    } else {
        const AVStream* stream = format->streams[streamIndex];
        const AVCodec* decoder = avcodec_find_decoder(stream->codecpar->codec_id);
        codec = avcodec_alloc_context3(decoder);
        avcodec_parameters_to_context(codec, stream->codecpar);
        if (!decoder || avcodec_open2(codec, decoder, nullptr) < 0) {
            out.error = "no decoder";
        } else {
            out.codec = decoder->name;
            out.width = codec->width;
            out.height = codec->height;
            out.fps = av_q2d(stream->avg_frame_rate);
            while (av_read_frame(format, packet) >= 0) {
                if (packet->stream_index == streamIndex && avcodec_send_packet(codec, packet) >= 0) collect();
                av_packet_unref(packet);
            }
            avcodec_send_packet(codec, nullptr);  // drain
            collect();
        }
    }
    sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
    return out;
}

// Mean absolute difference of two RGB8 frames, per channel, 0..255.
inline double meanAbsDifference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    if (a.size() != b.size() || a.empty()) return -1;
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(int(a[i]) - int(b[i]));
    return sum / double(a.size());
}

inline double meanValue(const std::vector<std::uint8_t>& rgb) {
    double sum = 0;
    for (std::uint8_t v : rgb) sum += v;
    return rgb.empty() ? 0 : sum / double(rgb.size());
}

}  // namespace penumbra::test
