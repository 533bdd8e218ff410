// Where the tests find the repository's scenes and the built `trazo` executable.
#pragma once

#include <string>
#include <vector>

namespace trazo::test {

std::string sourcePath(const std::string& relative);  // TRAZO_SOURCE_DIR/relative
std::string trazoBinary();                             // path of the built CLI
std::string tempPath(const std::string& name);         // a fresh path in a per-process temp dir
std::string readFileText(const std::string& path);     // whole file, empty when unreadable
// Writes `bytes` to tempPath(name) and returns that path.
std::string writeTempFile(const std::string& name, const std::string& bytes);
// A fresh, empty folder tempPath(name), so "nothing else was left behind" is a listing; and that listing, sorted.
std::string freshDir(const std::string& name);
std::vector<std::string> listDir(const std::string& dir);
std::vector<std::string> shippedSceneFiles();          // scenes/*.scene file names, sorted

// How a command ended: its exit status (-1 when a signal ended it) and what it wrote on stderr.
struct CommandResult {
    int status = -1;
    std::string errors;
};
// The shell command line `command`, its stdout dropped and its stdin empty.
CommandResult runCommand(const std::string& command);
// runCommand of the built CLI with `arguments`.
CommandResult runTrazo(const std::string& arguments);

}  // namespace trazo::test
