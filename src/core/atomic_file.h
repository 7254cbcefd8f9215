// Writing output files so that a failed or interrupted write never leaves a truncated image
// behind and never damages the file it was meant to replace: write a temporary file next to
// the target (same directory, so same filesystem), flush it to disk, then rename it over the
// target, which POSIX makes atomic.
#pragma once

#include <filesystem>
#include <functional>
#include <span>

namespace penumbra {

// Calls writeTmp with a fresh, empty temporary file path in the target's directory, then renames
// that file over target. On any failure the temporary file is removed, an existing target is left
// untouched, and penumbra::Error is thrown naming the target and the reason.
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path& tmp)>& writeTmp);

// The common case: the whole file is already in memory.
void writeBytesAtomically(const std::filesystem::path& target, std::span<const unsigned char> bytes);

// A file written piece by piece over a long time (a video): the pieces go to a temporary file
// beside the target, which commit() flushes and renames over the target. Destroyed without a
// commit (an error, Ctrl-C), it removes the temporary file: the target is never half written.
class PendingFile {
public:
    explicit PendingFile(const std::filesystem::path& target);
    ~PendingFile();
    PendingFile(const PendingFile&) = delete;
    PendingFile& operator=(const PendingFile&) = delete;

    const std::filesystem::path& tmp() const { return tmp_; }
    const std::filesystem::path& target() const { return target_; }
    void commit();  // Error naming the target on failure (the temporary file is then removed)

private:
    std::filesystem::path target_, tmp_;
    bool committed_ = false;
};

// Fails (penumbra::Error) if target could not be written later: its directory is missing or not
// writable, or target is itself a directory. Call before a long render so it is not wasted.
void checkWritable(const std::filesystem::path& target);

}  // namespace penumbra
