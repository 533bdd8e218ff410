// XXH64 (Yann Collet's xxHash, 64-bit, seed 0 by default): the hash of partial files' fingerprints and checksums.
// Host code. Streaming, so a file is hashed as it is written or read, in pieces of any size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace trazo {

class Xxhash64 {
public:
    explicit Xxhash64(uint64_t seed = 0);
    void update(const void* data, size_t size);
    uint64_t digest() const;  // of everything given so far; update() may go on after it

private:
    uint64_t acc_[4];
    uint64_t seed_;
    uint64_t total_ = 0;
    unsigned char buffer_[32];
    size_t buffered_ = 0;
};

uint64_t xxhash64(const void* data, size_t size, uint64_t seed = 0);
std::string hexHash(uint64_t hash);  // 16 lower-case hex digits

}  // namespace trazo
