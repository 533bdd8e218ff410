// XXH64 as specified in xxHash's doc/xxhash_spec.md (version 0.1.1): 4 lanes over 32-byte stripes, then the tail.
#include "render/xxhash64.h"

#include <cstdio>
#include <cstring>

namespace trazo {

namespace {

constexpr uint64_t kPrime1 = 0x9E3779B185EBCA87ull;
constexpr uint64_t kPrime2 = 0xC2B2AE3D27D4EB4Full;
constexpr uint64_t kPrime3 = 0x165667B19E3779F9ull;
constexpr uint64_t kPrime4 = 0x85EBCA77C2B2AE63ull;
constexpr uint64_t kPrime5 = 0x27D4EB2F165667C5ull;

uint64_t rotl(uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }
// Little-endian loads (the format's byte order on every host).
uint64_t read64(const unsigned char* p) {
    uint64_t v = 0;
    for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
    return v;
}
uint32_t read32(const unsigned char* p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24; }

uint64_t round(uint64_t acc, uint64_t lane) { return rotl(acc + lane * kPrime2, 31) * kPrime1; }
uint64_t mergeRound(uint64_t acc, uint64_t lane) { return (acc ^ round(0, lane)) * kPrime1 + kPrime4; }

}  // namespace

Xxhash64::Xxhash64(uint64_t seed)
    : acc_{seed + kPrime1 + kPrime2, seed + kPrime2, seed, seed - kPrime1}, seed_(seed), buffer_{} {}

void Xxhash64::update(const void* data, size_t size) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    total_ += size;
    if (buffered_ + size < 32) {
        if (size) std::memcpy(buffer_ + buffered_, p, size);
        buffered_ += size;
        return;
    }
    if (buffered_) {
        const size_t fill = 32 - buffered_;
        std::memcpy(buffer_ + buffered_, p, fill);
        for (int i = 0; i < 4; ++i) acc_[i] = round(acc_[i], read64(buffer_ + 8 * i));
        p += fill, size -= fill, buffered_ = 0;
    }
    uint64_t a0 = acc_[0], a1 = acc_[1], a2 = acc_[2], a3 = acc_[3];
    for (; size >= 32; p += 32, size -= 32) {
        a0 = round(a0, read64(p));
        a1 = round(a1, read64(p + 8));
        a2 = round(a2, read64(p + 16));
        a3 = round(a3, read64(p + 24));
    }
    acc_[0] = a0, acc_[1] = a1, acc_[2] = a2, acc_[3] = a3;
    if (size) std::memcpy(buffer_, p, size);
    buffered_ = size;
}

uint64_t Xxhash64::digest() const {
    uint64_t h;
    if (total_ >= 32) {
        h = rotl(acc_[0], 1) + rotl(acc_[1], 7) + rotl(acc_[2], 12) + rotl(acc_[3], 18);
        for (int i = 0; i < 4; ++i) h = mergeRound(h, acc_[i]);
    } else {
        h = seed_ + kPrime5;
    }
    h += total_;
    const unsigned char* p = buffer_;
    size_t left = buffered_;
    for (; left >= 8; p += 8, left -= 8) h = rotl(h ^ round(0, read64(p)), 27) * kPrime1 + kPrime4;
    if (left >= 4) {
        h = rotl(h ^ (uint64_t)read32(p) * kPrime1, 23) * kPrime2 + kPrime3;
        p += 4, left -= 4;
    }
    for (; left > 0; ++p, --left) h = rotl(h ^ (uint64_t)*p * kPrime5, 11) * kPrime1;
    h ^= h >> 33;
    h *= kPrime2;
    h ^= h >> 29;
    h *= kPrime3;
    h ^= h >> 32;
    return h;
}

uint64_t xxhash64(const void* data, size_t size, uint64_t seed) {
    Xxhash64 hash(seed);
    hash.update(data, size);
    return hash.digest();
}

std::string hexHash(uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", (unsigned long long)hash);
    return text;
}

}  // namespace trazo
