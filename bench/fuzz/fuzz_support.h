// Shared by the fuzz harnesses (bench/fuzz): where a fuzzed scene's relative paths resolve, a private temp
// file for readers that take only a path, and a bounded tiny render of what was read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo::fuzz {

// The largest input a harness looks at; longer ones return at once (libFuzzer's -max_len is set below it).
constexpr size_t kMaxInputBytes = size_t(1) << 20;

// The folder fuzzed scenes and CSG files resolve relative paths against: $TRAZO_FUZZ_ROOT, else the build's
// bench/fuzz/scene_root (small stand-ins for scenes/assets, so a seed scene reads in microseconds).
const std::string& sceneRoot();

// A path of this process's own (in a private mkdtemp folder, removed at exit) ending in `suffix`.
std::string privateTempPath(const std::string& suffix);

// Writes `size` bytes to `path`, replacing it; aborts when it cannot (a harness that cannot write its input
// tests nothing).
void writeFileOrDie(const std::string& path, const uint8_t* data, size_t size);

// flatten() and, when the estimated work is small, one pass of an 8 × 8 image on the CPU backend (one thread),
// read back and resolved: prepareMesh, the BVH build, the kernels and the resolve all see what was read.
void renderTiny(const Scene& scene);

// A scene around one object: a camera looking at the origin, a point light, an area light, one material.
Scene stageScene();

// renderTiny of `scene` with `object`, in material 0 (the stage's), added to its kind's array.
template <class Object>
void renderTinyWith(Scene scene, std::vector<Object> Scene::*array, Object object) {
    object.material = 0;
    (scene.*array).push_back(std::move(object));
    renderTiny(scene);
}

// A reader's contract: `what` (read is true) and no error, or nothing and an error. Dies where it is broken;
// returns `read`.
bool keptReadContract(bool read, const Diagnostics& diags, const std::string& reader, const std::string& what);

// Dies (abort, so libFuzzer and the replay driver record the input) with `what` on stderr.
[[noreturn]] void fail(const std::string& what);

}  // namespace trazo::fuzz
