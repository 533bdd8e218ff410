// Tests of FreeImageLock: what FreeImage reports reaches the holder of the lock, and the next holder starts clean.
#include "io/freeimage_lock.h"

#include <FreeImage.h>
#include <gtest/gtest.h>

#include <string>

namespace trazo {
namespace {

TEST(FreeImageLock, CapturesWhatFreeImageSaysWhileHeld) {
    // A PNG signature and then no valid chunk: libpng refuses it and FreeImage passes its reason on.
    std::string bytes("\x89PNG\r\n\x1a\n", 8);
    bytes += std::string(64, 'x');
    {
        const FreeImageLock freeImage;
        EXPECT_EQ(freeImage.message(), "");
        FIMEMORY* memory = FreeImage_OpenMemory(reinterpret_cast<BYTE*>(bytes.data()), DWORD(bytes.size()));
        ASSERT_NE(memory, nullptr);
        FIBITMAP* bitmap = FreeImage_LoadFromMemory(FIF_PNG, memory, 0);
        FreeImage_CloseMemory(memory);
        EXPECT_EQ(bitmap, nullptr);
        if (bitmap) FreeImage_Unload(bitmap);
        EXPECT_FALSE(freeImage.message().empty());
    }
    const FreeImageLock next;
    EXPECT_EQ(next.message(), "");
}

}  // namespace
}  // namespace trazo
