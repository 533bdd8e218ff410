// Where the tests find the repository's scenes and the built `trazo` executable.
#pragma once

#include <string>

namespace trazo::test {

std::string sourcePath(const std::string& relative);  // TRAZO_SOURCE_DIR/relative
std::string trazoBinary();                             // path of the built CLI
std::string tempPath(const std::string& name);         // a fresh path in a per-process temp dir
std::string readFileText(const std::string& path);     // whole file, empty when unreadable

}  // namespace trazo::test
