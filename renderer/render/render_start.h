// How a render starts, said alike by the CLI (--render) and the viewer (host): the backend it opens, or why it
// cannot.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "backends/backend.h"

namespace trazo {

// createBackendFor(*arrays, …), or createBackend(…) when `arrays` is null. Null after printing "trazo: cannot
// use the CUDA backend: WHY" on stderr; otherwise `fallback` says why an Auto choice did not use CUDA ("" when
// it did, or when the CPU was asked for).
std::unique_ptr<Backend> openBackend(BackendChoice choice, unsigned threads, const SceneArrays* arrays,
                                     std::string& fallback);

// "NAME (DEVICE)", followed by "; CUDA not used: FALLBACK" when `fallback` is not empty.
std::string describeBackend(const Backend& backend, const std::string& fallback);

}  // namespace trazo
