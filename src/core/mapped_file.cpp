#include "core/mapped_file.h"

#include <fstream>
#include <system_error>

#include "core/error.h"

#if defined(__unix__)
#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace penumbra {

MappedFile::MappedFile(const std::filesystem::path& path, std::size_t maxBytes, const char* what) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(
            "cannot open " + std::string(what) + " '" + path.string() + "': " +
            (std::filesystem::exists(path, ec) ? "it is not a regular file" : "no such file"));
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error("cannot read '" + path.string() + "': " + ec.message());
    if (size > maxBytes)
        throw Error("'" + path.string() + "' is too large (" + std::to_string(size >> 20) +
                    " MiB; the limit is " + std::to_string(maxBytes >> 20) + " MiB)");
    size_ = std::size_t(size);
    if (size_ == 0) return;
#if defined(__unix__)
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
        // MAP_POPULATE reads the file in at once instead of one page fault per 4 KiB later.
        void* p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        ::close(fd);
        if (p != MAP_FAILED) {
            data_ = static_cast<const char*>(p);
            mapped_ = true;
            return;
        }
    }
#endif
    std::ifstream in(path, std::ios::binary);
    copy_.resize(size_);
    if (!in || !in.read(copy_.data(), std::streamsize(size_)))
        throw Error("cannot read '" + path.string() + "'");
    data_ = copy_.data();
}

MappedFile::~MappedFile() {
#if defined(__unix__)
    if (mapped_) ::munmap(const_cast<char*>(data_), size_);
#endif
}

}  // namespace penumbra
