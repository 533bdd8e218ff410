// Xxhash64 over libxxhash's streaming state.
#include "render/xxhash64.h"

#include <cstdio>
#include <new>

#include <xxhash.h>

namespace trazo {

Xxhash64::Xxhash64(uint64_t seed) : state_(XXH64_createState()) {
    if (!state_) throw std::bad_alloc();
    XXH64_reset(state_, seed);
}

Xxhash64::~Xxhash64() { XXH64_freeState(state_); }

void Xxhash64::update(const void* data, size_t size) { XXH64_update(state_, data, size); }

uint64_t Xxhash64::digest() const { return XXH64_digest(state_); }

uint64_t xxhash64(const void* data, size_t size, uint64_t seed) { return XXH64(data, size, seed); }

std::string hexHash(uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", (unsigned long long)hash);
    return text;
}

}  // namespace trazo
