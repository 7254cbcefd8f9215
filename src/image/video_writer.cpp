#include "image/video_writer.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cctype>
#include <string>

#include "core/error.h"
#include "core/log.h"

namespace penumbra {
namespace {

std::string lowercaseExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string avError(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

}  // namespace

bool isVideoPath(const std::filesystem::path& path) {
    const std::string ext = lowercaseExtension(path);
    return ext == ".mp4" || ext == ".mkv" || ext == ".mov";
}

struct VideoWriter::Impl {
    std::string name;  // the target, for messages
    VideoSettings settings;
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    SwsContext* scaler = nullptr;
    std::uint64_t frames = 0;
    bool finished = false;

    ~Impl() {
        sws_freeContext(scaler);
        av_packet_free(&packet);
        av_frame_free(&frame);
        avcodec_free_context(&codec);
        if (format && format->pb && !(format->oformat->flags & AVFMT_NOFILE)) avio_closep(&format->pb);
        avformat_free_context(format);
    }

    [[noreturn]] void fail(const std::string& what, int code) const {
        throw Error("video '" + name + "': " + what + ": " + avError(code));
    }
    void check(int code, const char* what) const {
        if (code < 0) fail(what, code);
    }

    void openCodec(const AVCodec* encoder) {
        codec = avcodec_alloc_context3(encoder);
        if (!codec) throw std::bad_alloc();
        const AVRational rate = av_d2q(settings.fps, 100000);
        codec->width = int(settings.width);
        codec->height = int(settings.height);
        codec->framerate = rate;
        codec->time_base = av_inv_q(rate);
        codec->pix_fmt = AV_PIX_FMT_YUV420P;
        codec->gop_size = std::max(1, int(settings.fps * 2));  // a key frame every two seconds: seekable
        codec->colorspace = AVCOL_SPC_BT709;
        codec->color_primaries = AVCOL_PRI_BT709;
        codec->color_trc = AVCOL_TRC_IEC61966_2_1;  // the frames are sRGB-encoded
        codec->color_range = AVCOL_RANGE_MPEG;
        if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        av_opt_set_int(codec->priv_data, "crf", settings.crf, 0);  // libx264's; others ignore it
        av_opt_set(codec->priv_data, "preset", "medium", 0);
        check(avcodec_open2(codec, encoder, nullptr), "opening the H.264 encoder");
    }

    void openScaler() {
        const int w = int(settings.width), h = int(settings.height);
        scaler = sws_getContext(w, h, AV_PIX_FMT_RGB24, w, h, AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr,
                                nullptr);
        if (!scaler) throw Error("video '" + name + "': cannot convert RGB to YUV 4:2:0 at this size");
        // Full-range RGB in, BT.709 limited-range YUV out (what the stream's colour tags say).
        const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
        sws_setColorspaceDetails(scaler, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
        frame = av_frame_alloc();
        packet = av_packet_alloc();
        if (!frame || !packet) throw std::bad_alloc();
        frame->format = AV_PIX_FMT_YUV420P;
        frame->width = w;
        frame->height = h;
        check(av_frame_get_buffer(frame, 0), "allocating a frame");
    }

    // Hands a frame (null: flush) to the encoder and writes every packet it has ready.
    void encode(const AVFrame* input) {
        check(avcodec_send_frame(codec, input), "encoding");
        for (;;) {
            const int r = avcodec_receive_packet(codec, packet);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
            check(r, "encoding");
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            check(av_interleaved_write_frame(format, packet), "writing");  // takes the packet's data
        }
    }
};

VideoWriter::VideoWriter(const std::filesystem::path& file, const std::filesystem::path& container,
                         const VideoSettings& settings)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.name = container.string();
    m.settings = settings;
    if (settings.width == 0 || settings.height == 0 || settings.width % 2 || settings.height % 2)
        throw UsageError("an H.264 video needs an even width and height (got " + std::to_string(settings.width) + "x" +
                         std::to_string(settings.height) + ")");
    if (!(settings.fps > 0 && settings.fps <= 1000)) throw UsageError("a video's --fps must be above 0 and at most 1000");
    av_log_set_level(isVerbose() ? AV_LOG_INFO : AV_LOG_QUIET);  // failures become our own one-line errors
    const AVOutputFormat* oformat = av_guess_format(nullptr, container.string().c_str(), nullptr);
    if (!oformat || !isVideoPath(container))
        throw UsageError("cannot tell the video format of '" + m.name + "': use .mp4, .mkv or .mov");
    const AVCodec* encoder = avcodec_find_encoder_by_name("libx264");
    if (!encoder) encoder = avcodec_find_encoder(AV_CODEC_ID_H264);
    if (!encoder) throw Error("this FFmpeg has no H.264 encoder (Debian's libavcodec59 brings libx264)");
    m.check(avformat_alloc_output_context2(&m.format, oformat, nullptr, file.string().c_str()), "choosing the format");
    m.stream = avformat_new_stream(m.format, nullptr);
    if (!m.stream) throw std::bad_alloc();
    m.openCodec(encoder);
    m.check(avcodec_parameters_from_context(m.stream->codecpar, m.codec), "setting the stream up");
    m.stream->time_base = m.codec->time_base;
    m.stream->avg_frame_rate = m.codec->framerate;
    if (!(m.format->oformat->flags & AVFMT_NOFILE))
        m.check(avio_open(&m.format->pb, file.string().c_str(), AVIO_FLAG_WRITE), "opening the file");
    m.check(avformat_write_header(m.format, nullptr), "writing the header");
    m.openScaler();
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::addFrame(std::span<const std::uint8_t> rgb) {
    Impl& m = *impl_;
    PN_CHECK(!m.finished);
    PN_CHECK(rgb.size() == std::size_t(m.settings.width) * m.settings.height * 3);
    m.check(av_frame_make_writable(m.frame), "preparing a frame");
    const std::uint8_t* planes[1] = {rgb.data()};
    const int strides[1] = {int(m.settings.width) * 3};
    sws_scale(m.scaler, planes, strides, 0, int(m.settings.height), m.frame->data, m.frame->linesize);
    m.frame->pts = std::int64_t(m.frames++);
    m.encode(m.frame);
}

void VideoWriter::finish() {
    Impl& m = *impl_;
    PN_CHECK(!m.finished);
    m.finished = true;
    m.encode(nullptr);
    m.check(av_write_trailer(m.format), "writing the index");
    if (!(m.format->oformat->flags & AVFMT_NOFILE)) m.check(avio_closep(&m.format->pb), "closing the file");
}

std::uint64_t VideoWriter::frames() const { return impl_->frames; }

}  // namespace penumbra
