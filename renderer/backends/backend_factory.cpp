// createBackend(): picks CPU or CUDA (auto = CUDA when a device is present, else CPU).
#include "backends/backend.h"

namespace trazo {

#if defined(TRAZO_HAS_CUDA)
std::unique_ptr<Backend> createCudaBackend(std::string& error);  // backends/cuda/cuda_backend.cu
bool cudaDeviceAvailableImpl(std::string& deviceName);
std::unique_ptr<Backend> createCudaBackendOnImpl(int index, std::string& error);
int cudaDeviceCountImpl(std::string& why);
#endif

int cudaDeviceCount(std::string& why) {
#if defined(TRAZO_HAS_CUDA)
    return cudaDeviceCountImpl(why);
#else
    why = "this build of trazo has no CUDA backend (nvcc was not found at configure time)";
    return 0;
#endif
}

std::unique_ptr<Backend> createCudaBackendOn(int index, std::string& error) {
#if defined(TRAZO_HAS_CUDA)
    return createCudaBackendOnImpl(index, error);
#else
    (void)index;
    error = "this build of trazo has no CUDA backend (nvcc was not found at configure time)";
    return nullptr;
#endif
}

bool cudaDeviceAvailable(std::string& deviceName) {
#if defined(TRAZO_HAS_CUDA)
    return cudaDeviceAvailableImpl(deviceName);
#else
    deviceName.clear();
    return false;
#endif
}

std::unique_ptr<Backend> createBackend(BackendChoice choice, unsigned threads, std::string& error) {
    if (choice == BackendChoice::Cpu) return createCpuBackend(threads);
#if defined(TRAZO_HAS_CUDA)
    std::string device;
    if (cudaDeviceAvailableImpl(device)) {
        if (auto backend = createCudaBackend(error)) return backend;
    } else {
        error = "no CUDA device: " + device;
    }
#else
    error = "this build of trazo has no CUDA backend (nvcc was not found at configure time)";
#endif
    if (choice == BackendChoice::Cuda) return nullptr;
    return createCpuBackend(threads);
}

std::unique_ptr<Backend> createBackendFor(const SceneArrays& arrays, BackendChoice choice, unsigned threads,
                                          std::string& error) {
    std::unique_ptr<Backend> backend = createBackend(choice, threads, error);
    if (!backend || backend->accepts(arrays, error)) return backend;
    if (choice == BackendChoice::Auto) return createCpuBackend(threads);
    return nullptr;
}

}  // namespace trazo
