// FreeImageLock: FreeImage's process-wide state behind one lock (host). FreeImage is initialised once (needed
// when it is linked statically), and its message callback, which has no user pointer, reports to whoever holds
// the lock; every FreeImage call (the texture reader's, the image writer's) is made while holding it.
#pragma once

#include <mutex>
#include <string>

namespace trazo {

class FreeImageLock {
public:
    FreeImageLock();  // initialises FreeImage on first use, waits for the lock, clears the last message
    FreeImageLock(const FreeImageLock&) = delete;
    FreeImageLock& operator=(const FreeImageLock&) = delete;

    // What FreeImage last reported while this lock was held ("" when nothing).
    const std::string& message() const;

private:
    std::lock_guard<std::mutex> lock_;
};

}  // namespace trazo
