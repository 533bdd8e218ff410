// Tests of the shared file reader: only regular files are opened (a FIFO must not block), sizes are bounded
// before anything is allocated, and a NUL byte in a path is refused; and of the paths a file names.
#include "io/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <future>
#include <thread>

#include "test_paths.h"

namespace trazo {
namespace {

TEST(TextFile, ReadsARegularFileWhole) {
    const std::string path = test::writeTempFile("whole.txt", std::string("a\0b\nc", 5));
    std::string text, reason;
    ASSERT_TRUE(readWholeFile(path, text, reason)) << reason;
    EXPECT_EQ(text, std::string("a\0b\nc", 5));
}

TEST(TextFile, RefusesWhatIsNotARegularFile) {
    std::string text, reason;
    EXPECT_FALSE(readWholeFile("/nonexistent/trazo/x", text, reason));
    EXPECT_EQ(reason, "No such file or directory");
    EXPECT_FALSE(readWholeFile(test::tempPath(""), text, reason));
    EXPECT_EQ(reason, "Is a directory");
    EXPECT_FALSE(readWholeFile("/dev/zero", text, reason));  // would never end
    EXPECT_EQ(reason, "not a regular file (a character device)");
    EXPECT_FALSE(readWholeFile("/dev/null", text, reason));
    EXPECT_EQ(reason, "not a regular file (a character device)");
}

// A FIFO with no writer blocks an ordinary open for ever: the reader must refuse it without opening it. Run on
// a thread with a deadline; should it block, opening the write end releases it and the test fails.
TEST(TextFile, RefusesAFifoWithoutBlocking) {
    const std::string fifo = test::tempPath("text_file.fifo");
    std::filesystem::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::promise<std::pair<bool, std::string>> done;
    std::future<std::pair<bool, std::string>> result = done.get_future();
    std::thread reader([&] {
        std::string text, reason;
        const bool ok = readWholeFile(fifo, text, reason);
        done.set_value({ok, reason});
    });
    if (result.wait_for(std::chrono::seconds(10)) != std::future_status::ready) {
        ADD_FAILURE() << "readWholeFile blocked on a FIFO";
        const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);  // a reader is waiting: this opens
        if (fd >= 0) ::close(fd);
    }
    reader.join();
    const auto [ok, reason] = result.get();
    EXPECT_FALSE(ok);
    EXPECT_EQ(reason, "not a regular file (a FIFO)");
    std::string why;
    EXPECT_EQ(openRegularFile(fifo, why), -1);
    EXPECT_EQ(why, "not a regular file (a FIFO)");
    std::filesystem::remove(fifo);
}

TEST(TextFile, NulInAPathIsRefused) {
    const std::string path = test::writeTempFile("nul", "x");
    std::string text, reason;
    EXPECT_FALSE(readWholeFile(path + std::string("\0.obj", 5), text, reason));  // would open `path`
    EXPECT_EQ(reason, "the path contains a NUL byte");
}

// The size is checked before any allocation: a sparse file that claims 2^31 + 1 bytes costs nothing to make
// and is refused at once; a file one byte over a limit is refused, one at the limit is read.
TEST(TextFile, SizeIsBoundedBeforeReading) {
    const std::string sparse = test::writeTempFile("sparse.obj", "");
    ASSERT_EQ(::truncate(sparse.c_str(), (off_t(1) << 31) + 1), 0);
    std::string text, reason;
    EXPECT_FALSE(readWholeFile(sparse, text, reason));
    EXPECT_EQ(reason, "file too large (2147483649 bytes; the limit is 1073741824 bytes)");
    EXPECT_TRUE(text.empty());
    std::filesystem::remove(sparse);

    const std::string small = test::writeTempFile("limit.txt", std::string(1000, 'x'));
    EXPECT_FALSE(readWholeFile(small, text, reason, 999));
    EXPECT_EQ(reason, "file too large (1000 bytes; the limit is 999 bytes)");
    EXPECT_TRUE(readWholeFile(small, text, reason, 1000)) << reason;
    EXPECT_EQ(text.size(), 1000u);
}

TEST(TextFile, ASceneSizedReadReportsTheOsReason) {
    std::string text, reason;
    EXPECT_FALSE(readWholeFile("/nonexistent/trazo/file.scene", text, reason, kMaxSceneFileBytes));
    EXPECT_EQ(reason, "No such file or directory");
    EXPECT_FALSE(readWholeFile("/tmp", text, reason, kMaxSceneFileBytes));
    EXPECT_EQ(reason, "Is a directory");
    EXPECT_FALSE(readWholeFile("/dev/zero", text, reason, kMaxSceneFileBytes));
    EXPECT_EQ(reason, "not a regular file (a character device)");
}

TEST(TextFile, OpenRegularFileOpensOnlyRegularFiles) {
    std::string reason;
    EXPECT_LT(openRegularFile("/dev/null", reason), 0);
    EXPECT_EQ(reason, "not a regular file (a character device)");
    const int fd = openRegularFile(test::writeTempFile("readable.txt", "x"), reason);
    EXPECT_GE(fd, 0) << reason;
    if (fd >= 0) ::close(fd);
}

TEST(TextFile, RelativePathsResolveAgainstTheNamingFile) {
    EXPECT_EQ(resolveRelativePath("scenes/a.scene", "assets/b.obj"), "scenes/assets/b.obj");
    EXPECT_EQ(resolveRelativePath("scenes/sub/a.scene", "../c.csg"), "scenes/c.csg");
    EXPECT_EQ(resolveRelativePath("a.scene", "b.obj"), "b.obj");
    EXPECT_EQ(resolveRelativePath("scenes/a.scene", "/abs/b.obj"), "/abs/b.obj");
}

}  // namespace
}  // namespace trazo
