// The partial files' hash keeps its published values (XXH64(data, len, 0)), whole and in pieces: a file written
// by one build must read in another.
#include "render/xxhash64.h"

#include <gtest/gtest.h>

#include <string>

namespace trazo {
namespace {

std::string bytes771() {
    std::string s;
    for (int r = 0; r < 3; ++r)
        for (int i = 0; i < 256; ++i) s += (char)i;
    return s + "xyz";
}

TEST(Xxhash64, MatchesTheReferenceImplementation) {
    EXPECT_EQ(xxhash64("", 0), 0xef46db3751d8e999ull);
    EXPECT_EQ(xxhash64("a", 1), 0xd24ec4f1a98c6e5bull);
    EXPECT_EQ(xxhash64("abc", 3), 0x44bc2cf5ad770999ull);
    const std::string fox = "The quick brown fox jumps over the lazy dog";
    EXPECT_EQ(xxhash64(fox.data(), fox.size()), 0x0b242d361fda71bcull);
    const std::string long771 = bytes771();
    EXPECT_EQ(xxhash64(long771.data(), long771.size()), 0xe921a1b45bd779f8ull);
    EXPECT_EQ(hexHash(0xe921a1b45bd779f8ull), "e921a1b45bd779f8");
}

TEST(Xxhash64, PiecesOfAnySizeGiveTheWholeHash) {
    const std::string data = bytes771();
    for (size_t piece : {1u, 3u, 7u, 31u, 32u, 33u, 100u}) {
        Xxhash64 h;
        for (size_t at = 0; at < data.size(); at += piece)
            h.update(data.data() + at, std::min(piece, data.size() - at));
        EXPECT_EQ(h.digest(), 0xe921a1b45bd779f8ull) << "pieces of " << piece;
    }
}

}  // namespace
}  // namespace trazo
