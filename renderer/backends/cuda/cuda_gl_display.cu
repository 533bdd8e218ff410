// CUDA-GL interop for the viewer (host + one kernel): each pixel's estimate() goes straight from the
// accumulation buffer into the viewer's GL pixel buffer, with no copy through the host.
#include <cuda_runtime.h>
// After cuda_runtime.h; it includes <GL/gl.h> itself (only GLuint/GLenum are needed from it).
#include <cuda_gl_interop.h>

#include <string>

#include "core/accumulation.h"

namespace trazo {

namespace {

__global__ void resolveToRgbaKernel(const AccumPixel* accum, float4* rgba, uint32_t pixelCount) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= pixelCount) return;
    const Vec3 c = accum[i].estimate();  // the image resolveImage() makes on the host
    rgba[i] = make_float4(c.x, c.y, c.z, 1.0f);
}

bool failed(cudaError_t status, const char* call, std::string& why) {
    if (status == cudaSuccess) return false;
    why = std::string(call) + ": " + cudaGetErrorString(status);
    cudaGetLastError();  // clear it so the renderer's next check does not see it
    return true;
}

}  // namespace

// One registered GL buffer; registered again when the buffer or the image size changes.
class CudaGlDisplay {
public:
    ~CudaGlDisplay() { release(); }

    bool resolve(unsigned glBuffer, const AccumPixel* accum, uint32_t width, uint32_t height, std::string& why) {
        if (!resource_ || glBuffer != buffer_ || width != width_ || height != height_) {
            release();
            if (failed(cudaGraphicsGLRegisterBuffer(&resource_, glBuffer, cudaGraphicsRegisterFlagsWriteDiscard),
                       "cudaGraphicsGLRegisterBuffer", why)) {
                resource_ = nullptr;
                return false;
            }
            buffer_ = glBuffer;
            width_ = width;
            height_ = height;
        }
        if (failed(cudaGraphicsMapResources(1, &resource_), "cudaGraphicsMapResources", why)) return false;
        void* pointer = nullptr;
        size_t bytes = 0;
        const size_t pixels = size_t(width) * height;
        bool ok = !failed(cudaGraphicsResourceGetMappedPointer(&pointer, &bytes, resource_),
                          "cudaGraphicsResourceGetMappedPointer", why);
        if (ok && bytes < pixels * sizeof(float4)) {
            why = "the GL buffer is smaller than the image";
            ok = false;
        }
        if (ok && pixels) {
            const uint32_t block = 256;
            resolveToRgbaKernel<<<uint32_t((pixels + block - 1) / block), block>>>(accum, static_cast<float4*>(pointer),
                                                                                   uint32_t(pixels));
            ok = !failed(cudaGetLastError(), "resolveToRgbaKernel", why);
        }
        // Unmapping orders the kernel before any GL use of the buffer.
        if (failed(cudaGraphicsUnmapResources(1, &resource_), "cudaGraphicsUnmapResources", why)) ok = false;
        return ok;
    }

    void release() {
        if (resource_) cudaGraphicsUnregisterResource(resource_);
        resource_ = nullptr;
    }

private:
    cudaGraphicsResource* resource_ = nullptr;
    unsigned buffer_ = 0;
    uint32_t width_ = 0, height_ = 0;
};

CudaGlDisplay* createCudaGlDisplay() { return new CudaGlDisplay(); }
void releaseCudaGlDisplay(CudaGlDisplay& display) { display.release(); }
void destroyCudaGlDisplay(CudaGlDisplay* display) { delete display; }

bool resolveIntoGlBuffer(CudaGlDisplay& display, unsigned glBuffer, const AccumPixel* accum, uint32_t width,
                         uint32_t height, std::string& why) {
    return display.resolve(glBuffer, accum, width, height, why);
}

}  // namespace trazo
