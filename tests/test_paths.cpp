// Paths for the tests: the source tree, the CLI binary (and running it) and a per-process scratch folder.
#include "test_paths.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace trazo::test {

std::string sourcePath(const std::string& relative) { return std::string(TRAZO_SOURCE_DIR) + "/" + relative; }

std::string trazoBinary() { return TRAZO_BINARY; }

std::string tempPath(const std::string& name) {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("trazo_tests_" + std::to_string(getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    return (dir / name).string();
}

std::string readFileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string writeTempFile(const std::string& name, const std::string& bytes) {
    const std::string path = tempPath(name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

std::string freshDir(const std::string& name) {
    const std::string dir = tempPath(name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::vector<std::string> listDir(const std::string& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::vector<std::string> shippedSceneFiles() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath("scenes")))
        if (entry.path().extension() == ".scene") names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

CommandResult runCommand(const std::string& command) {
    const std::string errFile = tempPath("command_stderr.txt");
    const int raw = std::system((command + " 2>'" + errFile + "' >/dev/null </dev/null").c_str());
    return CommandResult{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, readFileText(errFile)};
}

CommandResult runTrazo(const std::string& arguments) { return runCommand(trazoBinary() + " " + arguments); }

}  // namespace trazo::test
