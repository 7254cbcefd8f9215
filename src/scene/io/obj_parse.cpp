#include "scene/io/obj_parse.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/big_buffer.h"
#include "core/error.h"
#include "core/parallel.h"

namespace penumbra::obj {
namespace {

constexpr std::size_t kChunkBytes = std::size_t(1) << 20;

// Counts of one chunk, from the first pass.
struct Counts {
    std::uint64_t lines = 0, v = 0, vt = 0, vn = 0, f = 0;
};

struct Chunk {
    std::string_view text;
    Counts counts, before;  // its own, and the sum over the chunks before it
    std::vector<Corner> corners;
    std::vector<std::uint32_t> faceSize;
    std::vector<std::uint32_t> faceLine;
    std::vector<MaterialUse> materials;  // firstFace counted within the chunk
    std::vector<std::string> libraries;
    std::string error;  // the first problem, already "name:line: ..."
};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r'; }

enum class Kind { Other, V, Vt, Vn, F, Usemtl, Mtllib };

// The statement a line starts with; `rest` is what follows the keyword.
Kind kindOf(std::string_view line, std::string_view& rest) {
    std::size_t i = 0;
    while (i < line.size() && isSpace(line[i])) ++i;
    std::size_t j = i;
    while (j < line.size() && !isSpace(line[j])) ++j;
    const std::string_view word = line.substr(i, j - i);
    rest = line.substr(j);
    if (word == "v") return Kind::V;
    if (word == "vt") return Kind::Vt;
    if (word == "vn") return Kind::Vn;
    if (word == "f") return Kind::F;
    if (word == "usemtl") return Kind::Usemtl;
    if (word == "mtllib") return Kind::Mtllib;
    return Kind::Other;
}

// Calls fn(line) for every line of `text`, without the line break.
template <typename Fn>
void forEachLine(std::string_view text, Fn&& fn) {
    const char* p = text.data();
    const char* end = p + text.size();
    while (p < end) {
        const char* nl = static_cast<const char*>(std::memchr(p, '\n', std::size_t(end - p)));
        const char* lineEnd = nl ? nl : end;
        fn(std::string_view(p, std::size_t(lineEnd - p)));
        p = nl ? nl + 1 : end;
    }
}

Counts count(std::string_view text) {
    Counts c;
    forEachLine(text, [&](std::string_view line) {
        ++c.lines;
        std::string_view rest;
        switch (kindOf(line, rest)) {
            case Kind::V:
                ++c.v;
                break;
            case Kind::Vt:
                ++c.vt;
                break;
            case Kind::Vn:
                ++c.vn;
                break;
            case Kind::F:
                ++c.f;
                break;
            default:
                break;
        }
    });
    return c;
}

std::string printable(std::string_view s) {
    std::string out(s.substr(0, 40));
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    return s.size() > 40 ? out + "..." : out;
}

struct LineError {
    std::string what;
};

// Reads the words of a statement: numbers, or face corners.
class Words {
public:
    explicit Words(std::string_view rest) : p_(rest.data()), end_(rest.data() + rest.size()) {}

    bool next(std::string_view& word) {
        while (p_ < end_ && isSpace(*p_)) ++p_;
        if (p_ == end_ || *p_ == '#') return false;  // a comment ends the statement
        const char* b = p_;
        while (p_ < end_ && !isSpace(*p_)) ++p_;
        word = {b, std::size_t(p_ - b)};
        return true;
    }

    // A float; `missing` when the statement has no more words (nullptr: one is required).
    float number(const float* missing = nullptr) {
        std::string_view w;
        if (!next(w)) {
            if (missing) return *missing;
            throw LineError{"the statement has too few numbers"};
        }
        float v = 0;
        const char* b = w.data() + (w.size() > 1 && w[0] == '+' ? 1 : 0);
        auto [end, ec] = std::from_chars(b, w.data() + w.size(), v);
        if (end != w.data() + w.size() ||
            (ec != std::errc{} && ec != std::errc::result_out_of_range))
            throw LineError{"expected a number, found '" + printable(w) + "'"};
        if (ec == std::errc::result_out_of_range)
            v = std::numeric_limits<float>::infinity();  // told apart below
        return v;
    }

private:
    const char* p_;
    const char* end_;
};

std::string indexText(std::int64_t oneBased) { return std::to_string(oneBased); }

// One index of a corner ("3", "-1"): 0-based, relative indices resolved against `defined`
// (the elements of that kind before this line); `total` elements exist in the whole file.
std::int32_t resolve(std::string_view text, std::uint64_t defined, std::uint64_t total,
                     const char* what) {
    std::int64_t k = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), k);
    if (ec != std::errc{} || end != text.data() + text.size())
        throw LineError{"expected an index, found '" + printable(text) + "'"};
    if (k == 0)
        throw LineError{std::string("face refers to ") + what + " 0, but OBJ numbers them from 1"};
    const std::int64_t index = k > 0 ? k - 1 : std::int64_t(defined) + k;
    if (index < 0)
        throw LineError{std::string("face refers to a ") + what +
                        " before the first (relative index " + std::to_string(k) + ")"};
    if (std::uint64_t(index) >= total)
        throw LineError{std::string("face refers to ") + what + " " + indexText(index + 1) +
                        ", but " + std::to_string(total) + " " + what +
                        (total == 1 ? " is" : "s are") + " defined"};
    return std::int32_t(index);
}

class ChunkParser {
public:
    ChunkParser(Chunk& chunk, Parsed& out, const Counts& total, const std::string& name)
        : c_(chunk), out_(out), total_(total), name_(name), counts_(chunk.before) {}

    void run() {
        std::uint64_t line = c_.before.lines;
        try {
            forEachLine(c_.text, [&](std::string_view text) {
                ++line;
                statement(text, line);
            });
        } catch (const LineError& e) {
            c_.error = name_ + ":" + std::to_string(line) + ": " + e.what;
        }
    }

private:
    void statement(std::string_view text, std::uint64_t line) {
        std::string_view rest;
        switch (kindOf(text, rest)) {
            case Kind::V:
                vertex(rest, line);
                break;
            case Kind::Vt: {
                Words w(rest);
                const float zero = 0;
                const float u = w.number(), v = w.number(&zero);
                float* t = &out_.texcoords[2 * counts_.vt++];
                t[0] = u;
                t[1] = v;
                break;
            }
            case Kind::Vn: {
                Words w(rest);
                float* n = &out_.normals[3 * counts_.vn++];
                for (int k = 0; k < 3; ++k) n[k] = w.number();
                break;
            }
            case Kind::F:
                face(rest, line);
                break;
            case Kind::Usemtl:
                c_.materials.push_back({std::uint32_t(c_.faceLine.size()), trimmed(rest)});
                break;
            case Kind::Mtllib: {
                Words w(rest);
                std::string_view file;
                while (w.next(file)) c_.libraries.emplace_back(file);
                break;
            }
            case Kind::Other:
                break;
        }
    }

    static std::string trimmed(std::string_view s) {
        while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
        while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
        return std::string(s);
    }

    void vertex(std::string_view rest, std::uint64_t line) {
        Words w(rest);
        const std::uint64_t i = counts_.v++;
        float* p = &out_.positions[3 * i];
        for (int k = 0; k < 3; ++k) p[k] = w.number();
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw LineError{"vertex " + std::to_string(i + 1) +
                            " has a coordinate that is not a finite number"};
        out_.positionLine[i] = std::uint32_t(std::min<std::uint64_t>(line, UINT32_MAX));
    }

    void face(std::string_view rest, std::uint64_t line) {
        Words w(rest);
        std::string_view word;
        std::uint32_t n = 0;
        while (w.next(word)) {
            Corner c;
            const std::size_t s1 = word.find('/');
            c.v = resolve(word.substr(0, s1), counts_.v, total_.v, "vertex");
            if (s1 != std::string_view::npos) {
                const std::string_view tail = word.substr(s1 + 1);
                const std::size_t s2 = tail.find('/');
                const std::string_view t = tail.substr(0, s2);
                if (!t.empty()) c.vt = resolve(t, counts_.vt, total_.vt, "texture coordinate");
                if (s2 != std::string_view::npos) {
                    const std::string_view nrm = tail.substr(s2 + 1);
                    if (!nrm.empty()) c.vn = resolve(nrm, counts_.vn, total_.vn, "normal");
                }
            }
            c_.corners.push_back(c);
            ++n;
        }
        c_.faceSize.push_back(n);
        c_.faceLine.push_back(std::uint32_t(std::min<std::uint64_t>(line, UINT32_MAX)));
    }

    Chunk& c_;
    Parsed& out_;
    const Counts& total_;
    const std::string& name_;
    Counts counts_;  // defined so far, over the whole file
};

// Cuts the text into chunks of about kChunkBytes that end at line breaks.
std::vector<Chunk> cut(std::string_view text) {
    std::vector<Chunk> chunks;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = std::min(text.size(), begin + kChunkBytes);
        if (end < text.size()) {
            const std::size_t nl = text.find('\n', end);
            end = nl == std::string_view::npos ? text.size() : nl + 1;
        }
        chunks.push_back({});
        chunks.back().text = text.substr(begin, end - begin);
        begin = end;
    }
    return chunks;
}

}  // namespace

Parsed parse(std::string_view text, const std::string& name) {
    std::vector<Chunk> chunks = cut(text);
    parallelFor(chunks.size(), 1, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t i = lo; i < hi; ++i) chunks[i].counts = count(chunks[i].text);
    });
    Counts total;
    for (Chunk& c : chunks) {
        c.before = total;
        total.lines += c.counts.lines;
        total.v += c.counts.v;
        total.vt += c.counts.vt;
        total.vn += c.counts.vn;
        total.f += c.counts.f;
    }
    if (total.v >= std::uint64_t(std::numeric_limits<std::int32_t>::max()) ||
        total.vt >= std::uint64_t(std::numeric_limits<std::int32_t>::max()) ||
        total.vn >= std::uint64_t(std::numeric_limits<std::int32_t>::max()))
        throw Error(name + ": too many vertices");

    Parsed out;
    // Exact sizes from the first pass; every thread fills its own part.
    out.positions = hugeVector<float>(3 * total.v);
    out.positionLine = hugeVector<std::uint32_t>(total.v);
    out.texcoords = hugeVector<float>(2 * total.vt);
    out.normals = hugeVector<float>(3 * total.vn);
    parallelFor(chunks.size(), 1, [&](std::size_t lo, std::size_t hi) {
        for (std::size_t i = lo; i < hi; ++i) {
            chunks[i].corners.reserve(chunks[i].counts.f * 3);
            chunks[i].faceSize.reserve(chunks[i].counts.f);
            chunks[i].faceLine.reserve(chunks[i].counts.f);
            ChunkParser(chunks[i], out, total, name).run();
        }
    });
    for (const Chunk& c : chunks)
        if (!c.error.empty()) throw Error(c.error);

    // Faces: concatenated in file order.
    std::size_t cornerCount = 0;
    for (const Chunk& c : chunks) cornerCount += c.corners.size();
    if (cornerCount >= std::numeric_limits<std::uint32_t>::max())
        throw Error(name + ": too many face corners");
    reserveHuge(out.corners, cornerCount);
    reserveHuge(out.faceStart, total.f + 1);
    reserveHuge(out.faceLine, total.f);
    out.faceStart.push_back(0);
    for (Chunk& c : chunks) {
        const auto firstFace = std::uint32_t(out.faceLine.size());
        for (MaterialUse& m : c.materials)
            out.materials.push_back({firstFace + m.firstFace, std::move(m.name)});
        for (std::string& l : c.libraries) out.libraries.push_back(std::move(l));
        out.corners.insert(out.corners.end(), c.corners.begin(), c.corners.end());
        out.faceLine.insert(out.faceLine.end(), c.faceLine.begin(), c.faceLine.end());
        for (std::uint32_t n : c.faceSize) out.faceStart.push_back(out.faceStart.back() + n);
        c.corners = {};
        c.faceLine = {};
    }
    return out;
}

}  // namespace penumbra::obj
