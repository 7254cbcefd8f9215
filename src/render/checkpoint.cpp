#include "render/checkpoint.h"

#include <xxhash.h>

#include <cstring>
#include <memory>
#include <span>

#include "core/atomic_file.h"
#include "core/error.h"
#include "scene/io/load.h"

namespace penumbra {
namespace {

constexpr char kMagic[8] = {'P', 'N', 'M', 'S', 'T', 'A', 'T', 'E'};
constexpr std::uint32_t kVersion = 1;
constexpr std::uint32_t kAdaptiveFlag = 1;

// The fixed part at the start of the file (host byte order: checkpoints stay on one machine).
struct Header {
    char magic[8];
    std::uint32_t version;
    std::uint32_t flags;
    std::uint64_t key[2];
    std::uint32_t width, height;
    std::uint32_t passesDone;
    std::uint32_t hasPending;
    std::uint64_t nominalSamples;
};
static_assert(sizeof(Header) == 56);

std::uint64_t payloadBytes(const Header& h) {
    const std::uint64_t n = std::uint64_t(h.width) * h.height;
    std::uint64_t bytes = n * (3 + 1) * sizeof(double);
    if (h.flags & kAdaptiveFlag) bytes += n * (3 * sizeof(double) + sizeof(std::uint32_t));
    if (h.hasPending) bytes += n * sizeof(Vec4);
    return bytes;
}

template <typename T>
void append(std::string& out, std::span<const T> items) {
    out.append(reinterpret_cast<const char*>(items.data()), items.size_bytes());
}

template <typename T>
std::vector<T> take(std::string_view bytes, std::size_t& at, std::size_t count) {
    std::vector<T> items(count);
    std::memcpy(items.data(), bytes.data() + at, count * sizeof(T));
    at += count * sizeof(T);
    return items;
}

struct StateFree {
    void operator()(XXH3_state_t* s) const { XXH3_freeState(s); }
};

}  // namespace

RenderKey renderKey(const Renderer& renderer, const AdaptiveSettings& adaptive) {
    std::unique_ptr<XXH3_state_t, StateFree> state(XXH3_createState());
    PN_CHECK(state != nullptr);
    XXH3_128bits_reset(state.get());
    auto add = [&](const void* data, std::size_t bytes) { XXH3_128bits_update(state.get(), data, bytes); };
    auto addVector = [&](const auto& v) {
        const std::uint64_t size = v.size();
        add(&size, sizeof size);
        add(v.data(), v.size() * sizeof(v[0]));
    };
    add(&kVersion, sizeof kVersion);
    const SceneArrays& a = renderer.sceneArrays();
    addVector(a.nodes);
    addVector(a.triVerts);
    addVector(a.triAttribs);
    addVector(a.triUvs);
    addVector(a.materials);
    addVector(a.lightRefs);
    addVector(a.lightNodes);
    addVector(a.lightTree);
    addVector(a.lightGrid);
    addVector(a.textures);
    addVector(a.texels);
    addVector(a.punctual);
    addVector(a.sphereLights);
    addVector(a.env.radiance);
    addVector(a.env.alias);
    add(renderer.frameUniforms().mapped(), sizeof(shader::FrameUniforms));
    const RenderSettings& s = renderer.settings();
    const std::uint32_t settings[] = {s.width, s.height, s.samplesPerPass, s.maxBounces, s.rouletteStart, s.seed,
                                      std::uint32_t(s.accel), std::uint32_t(s.mis), s.uniformLightPick ? 1u : 0u,
                                      roundPasses(adaptive), adaptive.minSamples, adaptive.tileSize};
    add(settings, sizeof settings);
    const float adaptiveFloats[] = {adaptive.threshold, adaptive.minProbability};
    add(adaptiveFloats, sizeof adaptiveFloats);
    const XXH128_hash_t h = XXH3_128bits_digest(state.get());
    return {h.low64, h.high64};
}

std::string encodeCheckpoint(const RenderSnapshot& snap, const RenderKey& key) {
    const AccumulatorData& d = snap.sums;
    Header h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.version = kVersion;
    h.flags = d.adaptive ? kAdaptiveFlag : 0;
    h.key[0] = key[0];
    h.key[1] = key[1];
    h.width = d.width;
    h.height = d.height;
    h.passesDone = snap.passesDone;
    h.hasPending = snap.pending.empty() ? 0 : 1;
    h.nominalSamples = d.nominalSamples;
    std::string out;
    out.reserve(sizeof h + payloadBytes(h) + sizeof(std::uint64_t));
    out.append(reinterpret_cast<const char*>(&h), sizeof h);
    append<double>(out, d.estimate);
    append<double>(out, d.squares);
    if (d.adaptive) {
        append<double>(out, d.raw);
        append<std::uint32_t>(out, d.count);
    }
    append<Vec4>(out, snap.pending);
    const std::uint64_t checksum = XXH3_64bits(out.data(), out.size());
    out.append(reinterpret_cast<const char*>(&checksum), sizeof checksum);
    return out;
}

RenderSnapshot decodeCheckpoint(std::string_view bytes, const RenderKey& key, std::uint32_t width,
                                std::uint32_t height, const std::string& name) {
    auto fail = [&](const std::string& what) { return Error(name + ": " + what); };
    if (bytes.size() < sizeof(Header) + sizeof(std::uint64_t) || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        throw fail("not a Penumbra checkpoint file");
    Header h;
    std::memcpy(&h, bytes.data(), sizeof h);
    if (h.version != kVersion)
        throw fail("checkpoint version " + std::to_string(h.version) + " was written by another Penumbra (this one reads " +
                   std::to_string(kVersion) + "); render afresh without --resume");
    if ((h.flags & ~kAdaptiveFlag) != 0 || h.hasPending > 1 || h.width == 0 || h.height == 0 ||
        std::uint64_t(h.width) * h.height > (std::uint64_t(1) << 32))
        throw fail("corrupt checkpoint header");
    if (std::uint64_t(bytes.size()) != sizeof h + payloadBytes(h) + sizeof(std::uint64_t))
        throw fail("checkpoint is truncated or has trailing data (" + std::to_string(bytes.size()) + " bytes)");
    std::uint64_t checksum;
    std::memcpy(&checksum, bytes.data() + bytes.size() - sizeof checksum, sizeof checksum);
    if (XXH3_64bits(bytes.data(), bytes.size() - sizeof checksum) != checksum)
        throw fail("checkpoint is corrupt (checksum mismatch)");
    if (h.key[0] != key[0] || h.key[1] != key[1])
        throw fail("checkpoint was made for another scene or other settings (scene, camera, --time, size, --seed, "
                   "--bounces, --noise-threshold and the like must match); render afresh without --resume");
    if (h.width != width || h.height != height)
        throw fail("checkpoint is " + std::to_string(h.width) + "x" + std::to_string(h.height) + ", not " +
                   std::to_string(width) + "x" + std::to_string(height));
    RenderSnapshot s;
    s.passesDone = h.passesDone;
    AccumulatorData& d = s.sums;
    d.width = h.width;
    d.height = h.height;
    d.adaptive = (h.flags & kAdaptiveFlag) != 0;
    d.nominalSamples = h.nominalSamples;
    const std::size_t n = std::size_t(h.width) * h.height;
    std::size_t at = sizeof h;
    d.estimate = take<double>(bytes, at, 3 * n);
    d.squares = take<double>(bytes, at, n);
    if (d.adaptive) {
        d.raw = take<double>(bytes, at, 3 * n);
        d.count = take<std::uint32_t>(bytes, at, n);
    }
    if (h.hasPending) s.pending = take<Vec4>(bytes, at, n);
    return s;
}

void writeCheckpoint(const std::filesystem::path& path, const RenderSnapshot& snapshot, const RenderKey& key) {
    const std::string bytes = encodeCheckpoint(snapshot, key);
    writeBytesAtomically(path, std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
}

RenderSnapshot readCheckpoint(const std::filesystem::path& path, const RenderKey& key, std::uint32_t width,
                              std::uint32_t height) {
    return decodeCheckpoint(readFileBytes(path, std::size_t(16) << 30), key, width, height, path.string());
}

}  // namespace penumbra
