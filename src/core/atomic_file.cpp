#include "core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "core/error.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHint = " (check that the directory exists and is writable)";

fs::path directoryOf(const fs::path& target) {
    fs::path dir = target.parent_path();
    return dir.empty() ? fs::path(".") : dir;
}

[[noreturn]] void failWrite(const fs::path& target, const std::string& reason) {
    throw Error("cannot write '" + target.string() + "': " + reason + kHint);
}

// Creates the temporary file with O_EXCL, so two processes (or two writes in one process) can
// never share one; the dot prefix keeps it out of casual directory listings.
fs::path createTempFile(const fs::path& target) {
    std::random_device rd;
    std::uniform_int_distribution<unsigned long long> dist;
    for (int attempt = 0; attempt < 8; ++attempt) {
        char suffix[64];
        std::snprintf(suffix, sizeof suffix, ".tmp.%ld.%016llx", static_cast<long>(::getpid()),
                      dist(rd));
        // Appended piecewise: GCC 12 gives a false -Wrestrict on "." + std::string.
        std::string name = ".";
        name += target.filename().string();
        name += suffix;
        fs::path tmp = directoryOf(target) / name;
        int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return tmp;
        }
        if (errno != EEXIST) failWrite(target, std::strerror(errno));
    }
    failWrite(target, "could not create a unique temporary file");
}

// Without this a crash shortly after the rename can leave a zero-length target on some
// filesystems (ext4 delayed allocation), which is exactly what the rename is meant to prevent.
void syncFile(const fs::path& path) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw Error(std::strerror(errno));
    int rc = ::fsync(fd);
    int err = errno;
    ::close(fd);
    if (rc != 0) throw Error(std::strerror(err));
}

}  // namespace

void writeFileAtomically(const fs::path& target,
                         const std::function<void(const fs::path& tmp)>& writeTmp) {
    if (target.filename().empty()) failWrite(target, "not a file name");
    fs::path tmp = createTempFile(target);
    std::string reason;
    try {
        writeTmp(tmp);
        syncFile(tmp);
        if (::rename(tmp.c_str(), target.c_str()) != 0) throw Error(std::strerror(errno));
        return;
    } catch (const std::exception& e) {
        reason = e.what();
    } catch (...) {
        reason = "unknown error";
    }
    std::error_code ignored;
    fs::remove(tmp, ignored);
    failWrite(target, reason);
}

PendingFile::PendingFile(const fs::path& target) : target_(target) {
    if (target.filename().empty()) failWrite(target, "not a file name");
    tmp_ = createTempFile(target);
}

PendingFile::~PendingFile() {
    if (committed_) return;
    std::error_code ignored;
    fs::remove(tmp_, ignored);
}

void PendingFile::commit() {
    PN_CHECK(!committed_);
    try {
        syncFile(tmp_);
        if (::rename(tmp_.c_str(), target_.c_str()) != 0) throw Error(std::strerror(errno));
        committed_ = true;
    } catch (const std::exception& e) {
        failWrite(target_, e.what());  // the destructor removes the temporary file
    }
}

void writeBytesAtomically(const fs::path& target, std::span<const unsigned char> bytes) {
    writeFileAtomically(target, [&](const fs::path& tmp) {
        // POSIX I/O rather than iostreams: write and close report errno (ENOSPC, EIO, EDQUOT),
        // which becomes the reason in the error message.
        int fd = ::open(tmp.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
        if (fd < 0) throw Error(std::strerror(errno));
        std::size_t done = 0;
        while (done < bytes.size()) {
            ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) {
                int err = errno;
                ::close(fd);
                throw Error(std::strerror(err));
            }
            done += static_cast<std::size_t>(n);
        }
        if (::close(fd) != 0) throw Error(std::strerror(errno));
    });
}

void checkWritable(const fs::path& target) {
    std::error_code ec;
    if (target.filename().empty() || fs::is_directory(target, ec)) {
        throw Error("cannot write '" + target.string() + "': it is a directory, not a file name");
    }
    fs::path dir = directoryOf(target);
    if (!fs::is_directory(dir, ec)) {
        throw Error("cannot write '" + target.string() + "': directory '" + dir.string() +
                    "' does not exist");
    }
    // Replacing the target is a rename, so only the directory's permissions matter.
    if (::access(dir.c_str(), W_OK | X_OK) != 0) {
        throw Error("cannot write '" + target.string() + "': directory '" + dir.string() +
                    "': " + std::strerror(errno));
    }
}

}  // namespace penumbra
