// Tests of replaceAtomically and the text writer on it: the target changes only on success, no temporary is
// ever left, and concurrent writers into one folder never share a temporary.
#include "io/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "io/text_file.h"
#include "test_paths.h"

namespace trazo {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) { return test::freshDir(name); }
std::vector<std::string> listDir(const fs::path& dir) { return test::listDir(dir.string()); }
std::string contents(const fs::path& path) { return test::readFileText(path.string()); }

TEST(AtomicFile, WritesThroughAHiddenTemporaryInTheSameFolder) {
    const fs::path dir = freshDir("atomic_ok");
    const fs::path path = dir / "out.txt";
    std::string seen, error;
    const bool ok = replaceAtomically(
        path.string(),
        [&](const std::string& temporary, std::string&) {
            seen = temporary;
            std::ofstream(temporary) << "new";
            return true;
        },
        error);
    ASSERT_TRUE(ok) << error;
    EXPECT_EQ(fs::path(seen).parent_path(), dir);
    EXPECT_EQ(fs::path(seen).filename().string().rfind(".out.txt.tmp", 0), 0u) << seen;
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.txt"});
    EXPECT_EQ(contents(path), "new");
}

TEST(AtomicFile, AFailedWriteLeavesTheTargetAndNoTemporary) {
    const fs::path dir = freshDir("atomic_fail");
    const fs::path path = dir / "out.txt";
    { std::ofstream(path) << "old"; }
    std::string error;
    const bool ok = replaceAtomically(
        path.string(),
        [&](const std::string& temporary, std::string& why) {
            std::ofstream(temporary) << "half";
            why = "the writer's own reason";
            return false;
        },
        error);
    EXPECT_FALSE(ok);
    EXPECT_EQ(error, "the writer's own reason");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.txt"});
    EXPECT_EQ(contents(path), "old");
}

TEST(AtomicFile, AFailedRenameSaysSoAndLeavesNoTemporary) {
    const fs::path dir = freshDir("atomic_rename");
    const fs::path path = dir / "out.txt";
    fs::create_directories(path / "inside");  // a non-empty folder cannot be renamed over
    std::string error;
    EXPECT_FALSE(writeTextFileAtomically(path.string(), "text", error));
    EXPECT_EQ(error.rfind("cannot write '" + path.string() + "': cannot replace it: ", 0), 0u) << error;
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.txt"});
    EXPECT_TRUE(fs::is_directory(path / "inside"));
}

TEST(AtomicFile, TextWriterReportsAMissingFolder) {
    const fs::path path = freshDir("atomic_missing") / "no_such_folder" / "out.txt";
    std::string error;
    EXPECT_FALSE(writeTextFileAtomically(path.string(), "text", error));
    EXPECT_EQ(error, "cannot write '" + path.string() + "': No such file or directory");
}

TEST(AtomicFile, ConcurrentWritersOfOneFileEachFinishWhole) {
    const fs::path dir = freshDir("atomic_threads");
    const fs::path path = dir / "out.txt";
    std::vector<std::thread> writers;
    std::vector<int> failures(8, 0);
    for (int t = 0; t < 8; ++t) {
        writers.emplace_back([&, t] {
            const std::string text(10000, char('a' + t));
            for (int i = 0; i < 20; ++i) {
                std::string error;
                if (!writeTextFileAtomically(path.string(), text, error)) ++failures[t];
            }
        });
    }
    for (std::thread& w : writers) w.join();
    for (int t = 0; t < 8; ++t) EXPECT_EQ(failures[t], 0) << "writer " << t;
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.txt"});
    const std::string last = contents(path);
    ASSERT_EQ(last.size(), 10000u);
    EXPECT_EQ(last, std::string(10000, last[0]));  // one writer's text, never a mix
}

}  // namespace
}  // namespace trazo
