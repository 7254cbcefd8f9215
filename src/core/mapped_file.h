// A whole file's bytes, read-only, for loaders of big files: memory-mapped where the system
// allows it (no copy, no zeroed buffer: the page cache is the buffer), else read into memory.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace penumbra {

class MappedFile {
public:
    // Throws Error naming the file when it is missing, not a regular file, unreadable, or larger
    // than maxBytes (`what` names the kind of file in that message, e.g. "PLY file").
    MappedFile(const std::filesystem::path& path, std::size_t maxBytes, const char* what = "file");
    ~MappedFile();
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;

    std::string_view bytes() const { return {data_, size_}; }

private:
    const char* data_ = nullptr;
    std::size_t size_ = 0;
    bool mapped_ = false;
    std::string copy_;  // when mapping is not possible
};

}  // namespace penumbra
