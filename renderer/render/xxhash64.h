// XXH64 (xxHash's 64-bit hash, from Debian's libxxhash): the hash of partial files' fingerprints and
// checksums. Host code. Streaming, so a file is hashed as it is written or read, in pieces of any size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

struct XXH64_state_s;

namespace trazo {

class Xxhash64 {
public:
    explicit Xxhash64(uint64_t seed = 0);
    ~Xxhash64();
    Xxhash64(const Xxhash64&) = delete;
    Xxhash64& operator=(const Xxhash64&) = delete;
    void update(const void* data, size_t size);
    uint64_t digest() const;  // of everything given so far; update() may go on after it

private:
    XXH64_state_s* state_;
};

uint64_t xxhash64(const void* data, size_t size, uint64_t seed = 0);
std::string hexHash(uint64_t hash);  // 16 lower-case hex digits

}  // namespace trazo
