// Where the tests find the repository's scenes and the built `trazo` executable.
#pragma once

#include <string>
#include <vector>

namespace trazo::test {

std::string sourcePath(const std::string& relative);  // TRAZO_SOURCE_DIR/relative
std::string trazoBinary();                             // path of the built CLI
std::string tempPath(const std::string& name);         // a fresh path in a per-process temp dir
std::string readFileText(const std::string& path);     // whole file, empty when unreadable
// A fresh, empty folder tempPath(name), so "nothing else was left behind" is a listing; and that listing, sorted.
std::string freshDir(const std::string& name);
std::vector<std::string> listDir(const std::string& dir);
std::vector<std::string> shippedSceneFiles();          // scenes/*.scene file names, sorted

}  // namespace trazo::test
