#include "core/atomic_file.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "test_dir.h"

namespace penumbra {
namespace {

using test::TempDir;

TEST(AtomicFile, WritesThroughTempInSameDirectory) {
    TempDir dir;
    std::filesystem::path seen;
    writeFileAtomically(dir / "out.txt", [&](const std::filesystem::path& tmp) {
        seen = tmp;
        EXPECT_EQ(tmp.parent_path(), dir.path());
        EXPECT_TRUE(std::filesystem::exists(tmp));  // reserved with O_EXCL before the callback
        test::writeAll(tmp, "hello");
    });
    EXPECT_NE(seen.filename(), "out.txt");
    EXPECT_EQ(test::readAll(dir / "out.txt"), "hello");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, FailedWriteLeavesOldFileByteIdenticalAndNoTemp) {
    TempDir dir;
    const std::string old = std::string("old\0bytes\n", 10);
    test::writeAll(dir / "out.png", old);
    try {
        writeFileAtomically(dir / "out.png", [](const std::filesystem::path& tmp) {
            test::writeAll(tmp, "partial");
            throw std::runtime_error("encoder exploded");
        });
        FAIL() << "no exception";
    } catch (const Error& e) {
        std::string msg = e.what();
        EXPECT_NE(msg.find("out.png"), std::string::npos) << msg;
        EXPECT_NE(msg.find("encoder exploded"), std::string::npos) << msg;
    }
    EXPECT_EQ(test::readAll(dir / "out.png"), old);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.png"});
}

TEST(AtomicFile, RenameOntoDirectoryFailsCleanly) {
    TempDir dir;
    std::filesystem::create_directory(dir / "sub");
    test::writeAll(dir / "sub" / "keep", "x");
    EXPECT_THROW(writeBytesAtomically(dir / "sub", std::span<const unsigned char>()), Error);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"sub"});
    EXPECT_EQ(test::readAll(dir / "sub" / "keep"), "x");
}

TEST(AtomicFile, WriteBytes) {
    TempDir dir;
    const unsigned char bytes[] = {0, 1, 2, 255};
    writeBytesAtomically(dir / "b.bin", bytes);
    EXPECT_EQ(test::readAll(dir / "b.bin"), std::string("\0\1\2\xff", 4));
}

TEST(CheckWritable, AcceptsFileInExistingDirectory) {
    TempDir dir;
    EXPECT_NO_THROW(checkWritable(dir / "new.png"));
    test::writeAll(dir / "existing.png", "x");
    EXPECT_NO_THROW(checkWritable(dir / "existing.png"));
    EXPECT_TRUE(std::filesystem::exists(dir / "existing.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "new.png"));  // checking creates nothing
}

TEST(CheckWritable, RejectsDirectoryTarget) {
    TempDir dir;
    EXPECT_THROW(checkWritable(dir.path()), Error);
    EXPECT_THROW(checkWritable(dir.path() / ""), Error);  // trailing slash
}

TEST(CheckWritable, RejectsMissingDirectory) {
    TempDir dir;
    try {
        checkWritable(dir / "missing" / "a.png");
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace penumbra
