// openBackend, describeBackend: the start of a render's report on stderr.
#include "render/render_start.h"

#include <cstdio>

namespace trazo {

std::unique_ptr<Backend> openBackend(BackendChoice choice, unsigned threads, const SceneArrays* arrays,
                                     std::string& fallback) {
    fallback.clear();
    std::unique_ptr<Backend> backend = arrays ? createBackendFor(*arrays, choice, threads, fallback)
                                              : createBackend(choice, threads, fallback);
    if (!backend) std::fprintf(stderr, "trazo: cannot use the CUDA backend: %s\n", fallback.c_str());
    return backend;
}

std::string describeBackend(const Backend& backend, const std::string& fallback) {
    std::string text = backend.name() + " (" + backend.deviceName() + ")";
    if (!fallback.empty()) text += "; CUDA not used: " + fallback;
    return text;
}

}  // namespace trazo
