// The scene assets scripts/setup.sh fetches rather than the repository holding them (the Stanford bunny), for
// the tests (host): a test of a scene that uses one skips, with the reason given here, when it is absent.
#pragma once

#include <filesystem>
#include <string>

#include "test_paths.h"

namespace trazo::test {

// "" when every fetched asset the scene file names is there; otherwise which one is missing and why.
inline std::string absentFetchedAsset(const std::string& sceneFile) {
    const std::filesystem::path bunny = std::filesystem::path(sceneFile).parent_path() / "assets" / "bunny.obj";
    if (readFileText(sceneFile).find("assets/bunny.obj") == std::string::npos || std::filesystem::exists(bunny))
        return {};
    return std::filesystem::path(sceneFile).filename().string() + " needs " + bunny.string() +
           ", which is absent (scripts/setup.sh fetches it)";
}

}  // namespace trazo::test
