// FreeImageLock: the one FreeImage mutex, its one-time initialisation and its captured output message.
#include "io/freeimage_lock.h"

#include <FreeImage.h>

namespace trazo {
namespace {

std::mutex gFreeImageMutex;
std::string gFreeImageMessage;  // written only under gFreeImageMutex (FreeImage calls back on the caller's thread)

void captureFreeImageMessage(FREE_IMAGE_FORMAT, const char* message) { gFreeImageMessage = message ? message : ""; }

std::mutex& initialisedMutex() {
    // Harmless when the shared library already initialised itself.
    static std::once_flag once;
    std::call_once(once, [] {
        FreeImage_Initialise(FALSE);
        FreeImage_SetOutputMessage(captureFreeImageMessage);
    });
    return gFreeImageMutex;
}

}  // namespace

FreeImageLock::FreeImageLock() : lock_(initialisedMutex()) { gFreeImageMessage.clear(); }

const std::string& FreeImageLock::message() const { return gFreeImageMessage; }

}  // namespace trazo
