// egl_interop_probe: exercises trazo's viewer interop (renderer/backends/cuda/cuda_gl_display.cu, linked
// from the build's libtrazo_cuda.a) on a headless EGL context, without GLFW or a display. Built only by
// scripts/gpu_prepare.sh (never by the normal build) and run by scripts/gpu_check.sh on a GPU machine.
//
// Why: the viewer opens its context with GLFW 3.3 (X11/GLX only), so on a headless GPU machine it cannot
// start at all; this probe checks the same CUDA-GL code path on the context a headless NVIDIA machine does
// have (EGL_EXT_platform_device). It also checks the failure path on a GL context CUDA cannot share
// (Mesa llvmpipe here, or no context at all): resolveIntoGlBuffer must return false with a reason and
// leave no sticky CUDA error, so the viewer can fall back to the host copy.
//
// EGL and GL are loaded with dlopen (no -dev packages needed to build it). Exit status: 0 all checks
// passed, 1 a check failed, 77 nothing to check (no libEGL / no EGL display).
//
// Build (scripts/gpu_prepare.sh does this): g++ -O2 -std=c++20 -I<src>/renderer -I/usr/local/cuda/include
//   egl_interop_probe.cpp <build>/renderer/libtrazo_cuda.a /usr/local/cuda/lib64/libcudart_static.a -ldl -lpthread -lrt
#include <cuda_runtime.h>
#include <dlfcn.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/accumulation.h"

namespace trazo {
class CudaGlDisplay;
CudaGlDisplay* createCudaGlDisplay();
void releaseCudaGlDisplay(CudaGlDisplay& display);
void destroyCudaGlDisplay(CudaGlDisplay* display);
bool resolveIntoGlBuffer(CudaGlDisplay& display, unsigned glBuffer, const AccumPixel* accum, uint32_t width,
                         uint32_t height, std::string& why);
}  // namespace trazo

namespace {

using EGLDisplay = void*;
using EGLConfig = void*;
using EGLContext = void*;
using EGLSurface = void*;
using EGLDeviceEXT = void*;
using EGLint = int32_t;
using EGLBoolean = unsigned;
using EGLenum = unsigned;
using EGLAttrib = intptr_t;

constexpr EGLint EGL_NONE = 0x3038, EGL_SURFACE_TYPE = 0x3033, EGL_PBUFFER_BIT = 0x0001,
                 EGL_RENDERABLE_TYPE = 0x3040, EGL_OPENGL_BIT = 0x0008, EGL_RED_SIZE = 0x3024,
                 EGL_GREEN_SIZE = 0x3023, EGL_BLUE_SIZE = 0x3022, EGL_ALPHA_SIZE = 0x3021, EGL_WIDTH = 0x3057,
                 EGL_HEIGHT = 0x3056, EGL_CONTEXT_MAJOR_VERSION = 0x3098, EGL_CONTEXT_MINOR_VERSION = 0x30FB,
                 EGL_CONTEXT_OPENGL_PROFILE_MASK = 0x30FD, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT = 0x0001,
                 EGL_VENDOR = 0x3053, EGL_VERSION = 0x3054, EGL_EXTENSIONS = 0x3055, EGL_CLIENT_APIS = 0x308D,
                 EGL_CUDA_DEVICE_NV = 0x323A, EGL_DRM_DEVICE_FILE_EXT = 0x3233;
constexpr EGLenum EGL_OPENGL_API = 0x30A2, EGL_PLATFORM_DEVICE_EXT = 0x313F;

constexpr unsigned GL_PIXEL_UNPACK_BUFFER = 0x88EC, GL_STREAM_DRAW = 0x88E0, GL_VENDOR = 0x1F00,
                   GL_RENDERER = 0x1F01, GL_VERSION = 0x1F02;

struct Egl {
    void* lib = nullptr;
    void* (*getProcAddress)(const char*) = nullptr;
    EGLint (*getError)() = nullptr;
    const char* (*queryString)(EGLDisplay, EGLint) = nullptr;
    EGLBoolean (*initialize)(EGLDisplay, EGLint*, EGLint*) = nullptr;
    EGLBoolean (*terminate)(EGLDisplay) = nullptr;
    EGLBoolean (*bindApi)(EGLenum) = nullptr;
    EGLBoolean (*chooseConfig)(EGLDisplay, const EGLint*, EGLConfig*, EGLint, EGLint*) = nullptr;
    EGLSurface (*createPbufferSurface)(EGLDisplay, EGLConfig, const EGLint*) = nullptr;
    EGLContext (*createContext)(EGLDisplay, EGLConfig, EGLContext, const EGLint*) = nullptr;
    EGLBoolean (*makeCurrent)(EGLDisplay, EGLSurface, EGLSurface, EGLContext) = nullptr;
    EGLBoolean (*destroyContext)(EGLDisplay, EGLContext) = nullptr;
    EGLBoolean (*queryDevices)(EGLint, EGLDeviceEXT*, EGLint*) = nullptr;
    const char* (*queryDeviceString)(EGLDeviceEXT, EGLint) = nullptr;
    EGLBoolean (*queryDeviceAttrib)(EGLDeviceEXT, EGLint, EGLAttrib*) = nullptr;
    EGLDisplay (*getPlatformDisplay)(EGLenum, void*, const EGLint*) = nullptr;
    EGLDisplay (*getDisplay)(void*) = nullptr;
};

struct Gl {
    const unsigned char* (*getString)(unsigned) = nullptr;
    unsigned (*getError)() = nullptr;
    void (*genBuffers)(int, unsigned*) = nullptr;
    void (*deleteBuffers)(int, const unsigned*) = nullptr;
    void (*bindBuffer)(unsigned, unsigned) = nullptr;
    void (*bufferData)(unsigned, intptr_t, const void*, unsigned) = nullptr;
    void (*getBufferSubData)(unsigned, intptr_t, intptr_t, void*) = nullptr;
    void (*finish)() = nullptr;
};

template <class F>
bool load(F& f, void* lib, void* (*gpa)(const char*), const char* name) {
    void* p = lib ? dlsym(lib, name) : nullptr;
    if (!p && gpa) p = gpa(name);
    f = reinterpret_cast<F>(p);
    return p != nullptr;
}

int failures = 0, checks = 0;
void check(bool ok, const std::string& what) {
    ++checks;
    if (!ok) ++failures;
    std::printf("  [%s] %s\n", ok ? "ok" : "FAIL", what.c_str());
}

bool hasWord(const char* list, const char* word) {
    if (!list) return false;
    const size_t n = std::strlen(word);
    for (const char* p = list; (p = std::strstr(p, word)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

// Accumulation with known estimates: pixel i has count 1 + (i + salt) % 5 (0 for every 11th: black) and
// sum = estimate · count; the expected RGBA is the host's AccumPixel::estimate(), what resolveImage() shows.
std::vector<trazo::AccumPixel> makeAccum(uint32_t w, uint32_t h, uint32_t salt, std::vector<float>& expected) {
    std::vector<trazo::AccumPixel> a(size_t(w) * h);
    expected.assign(a.size() * 4, 0.0f);
    for (size_t i = 0; i < a.size(); ++i) {
        const double count = (i + salt) % 11 == 0 ? 0.0 : double(1 + (i + salt) % 5);
        const double e[3] = {double(i % 97) / 97.0, double((i * 7 + salt) % 13) / 13.0, 0.25 + double(salt % 3)};
        for (int c = 0; c < 3; ++c) {
            a[i].sum[c] = e[c] * count;
            a[i].sumB[c] = 0.0;
        }
        a[i].count = count;
        a[i].countB = 0.0;
        const trazo::Vec3 r = a[i].estimate();  // black when count is 0
        expected[4 * i + 0] = r.x, expected[4 * i + 1] = r.y, expected[4 * i + 2] = r.z;
        expected[4 * i + 3] = 1.0f;
    }
    return a;
}

struct Outcome {
    bool resolved = false;
    std::string why;
    double maxError = 0.0;
    size_t bad = 0;
};

// Uploads an accumulation, resolves it into `pbo` through trazo's interop code, reads the buffer back.
Outcome resolveAndCompare(const Gl& gl, trazo::CudaGlDisplay& display, unsigned pbo, uint32_t w, uint32_t h,
                          uint32_t salt) {
    Outcome o;
    std::vector<float> expected;
    const std::vector<trazo::AccumPixel> host = makeAccum(w, h, salt, expected);
    trazo::AccumPixel* device = nullptr;
    if (cudaMalloc(&device, host.size() * sizeof(trazo::AccumPixel)) == cudaSuccess)
        cudaMemcpy(device, host.data(), host.size() * sizeof(trazo::AccumPixel), cudaMemcpyHostToDevice);
    else
        device = nullptr, cudaGetLastError();  // no CUDA: registration fails before any kernel could run
    o.resolved = trazo::resolveIntoGlBuffer(display, pbo, device, w, h, o.why);
    if (o.resolved) {
        std::vector<float> got(expected.size(), -1.0f);
        gl.bindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo);
        gl.getBufferSubData(GL_PIXEL_UNPACK_BUFFER, 0, intptr_t(got.size() * sizeof(float)), got.data());
        gl.bindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        for (size_t k = 0; k < got.size(); ++k) {
            const double err = std::fabs(double(got[k]) - expected[k]);
            // The sums are doubles and double division is exact under --use_fast_math too, so the device should
            // give the host's value; one float ulp is allowed (and reported as the max error).
            if (!(err <= 2.4e-7 * std::fmax(1.0, std::fabs(expected[k])))) ++o.bad;
            if (err > o.maxError || err != err) o.maxError = err;
        }
    }
    cudaFree(device);
    return o;
}

unsigned makeBuffer(const Gl& gl, size_t bytes) {
    unsigned pbo = 0;
    gl.genBuffers(1, &pbo);
    gl.bindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo);
    gl.bufferData(GL_PIXEL_UNPACK_BUFFER, intptr_t(bytes), nullptr, GL_STREAM_DRAW);
    gl.bindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    return pbo;
}

// What the viewer does on a resize (ui/view/display.cpp): let go of the interop registration, then re-specify the
// buffer's store (Display::allocate); the next resolve registers it again.
void respecify(const Gl& gl, trazo::CudaGlDisplay& display, unsigned pbo, size_t bytes) {
    trazo::releaseCudaGlDisplay(display);
    gl.bindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo);
    gl.bufferData(GL_PIXEL_UNPACK_BUFFER, intptr_t(bytes), nullptr, GL_STREAM_DRAW);
    gl.bindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

}  // namespace

int main(int argc, char** argv) {
    bool timing = true;
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "--no-timing")) timing = false;

    int cudaCount = 0;
    const cudaError_t cudaStatus = cudaGetDeviceCount(&cudaCount);
    const bool haveCuda = cudaStatus == cudaSuccess && cudaCount > 0;
    if (!haveCuda) cudaGetLastError();
    std::string cudaName = haveCuda ? "" : std::string("none (") + cudaGetErrorString(cudaStatus) + ")";
    if (haveCuda) {
        cudaDeviceProp prop{};
        cudaGetDeviceProperties(&prop, 0);
        cudaName = std::string(prop.name) + ", sm_" + std::to_string(prop.major) + std::to_string(prop.minor);
    }
    std::printf("egl_interop_probe: CUDA device 0: %s\n", cudaName.c_str());

    Egl egl;
    egl.lib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_GLOBAL);
    if (!egl.lib) {
        std::printf("SKIP: cannot load libEGL.so.1 (%s)\n", dlerror());
        return 77;
    }
    load(egl.getProcAddress, egl.lib, nullptr, "eglGetProcAddress");
    auto gpa = egl.getProcAddress;
    bool ok = load(egl.getError, egl.lib, gpa, "eglGetError") && load(egl.queryString, egl.lib, gpa, "eglQueryString") &&
              load(egl.initialize, egl.lib, gpa, "eglInitialize") && load(egl.terminate, egl.lib, gpa, "eglTerminate") &&
              load(egl.bindApi, egl.lib, gpa, "eglBindAPI") && load(egl.chooseConfig, egl.lib, gpa, "eglChooseConfig") &&
              load(egl.createPbufferSurface, egl.lib, gpa, "eglCreatePbufferSurface") &&
              load(egl.createContext, egl.lib, gpa, "eglCreateContext") &&
              load(egl.makeCurrent, egl.lib, gpa, "eglMakeCurrent") &&
              load(egl.destroyContext, egl.lib, gpa, "eglDestroyContext") && load(egl.getDisplay, egl.lib, gpa, "eglGetDisplay");
    if (!ok) {
        std::printf("SKIP: libEGL.so.1 lacks core EGL entry points\n");
        return 77;
    }
    const char* clientExtensions = egl.queryString(nullptr, EGL_EXTENSIONS);
    std::printf("EGL client extensions: %s\n", clientExtensions ? clientExtensions : "(none)");
    load(egl.queryDevices, nullptr, gpa, "eglQueryDevicesEXT");
    load(egl.queryDeviceString, nullptr, gpa, "eglQueryDeviceStringEXT");
    load(egl.queryDeviceAttrib, nullptr, gpa, "eglQueryDeviceAttribEXT");
    load(egl.getPlatformDisplay, nullptr, gpa, "eglGetPlatformDisplayEXT");

    // Pick the EGL device that is CUDA device 0 (EGL_NV_device_cuda), else the first device.
    EGLDisplay display = nullptr;
    std::string chosen;
    if (egl.queryDevices && egl.getPlatformDisplay && hasWord(clientExtensions, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[16];
        EGLint n = 0;
        egl.queryDevices(16, devices, &n);
        std::printf("EGL devices: %d\n", n);
        int pick = -1;
        for (EGLint i = 0; i < n; ++i) {
            const char* ext = egl.queryDeviceString ? egl.queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
            const char* drm = hasWord(ext, "EGL_EXT_device_drm") && egl.queryDeviceString
                                  ? egl.queryDeviceString(devices[i], EGL_DRM_DEVICE_FILE_EXT)
                                  : nullptr;
            EGLAttrib cudaOrdinal = -1;
            if (hasWord(ext, "EGL_NV_device_cuda") && egl.queryDeviceAttrib)
                egl.queryDeviceAttrib(devices[i], EGL_CUDA_DEVICE_NV, &cudaOrdinal);
            std::printf("  device %d: cuda=%ld drm=%s ext=%s\n", i, long(cudaOrdinal), drm ? drm : "-", ext ? ext : "-");
            if (cudaOrdinal == 0 && pick < 0) pick = i;
        }
        if (pick < 0 && n > 0) pick = 0;
        if (pick >= 0) {
            display = egl.getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[pick], nullptr);
            chosen = "EGL device " + std::to_string(pick);
        }
    }
    if (!display) {
        display = egl.getDisplay(nullptr);  // EGL_DEFAULT_DISPLAY
        chosen = "EGL_DEFAULT_DISPLAY";
    }
    EGLint major = 0, minor = 0;
    if (!display || !egl.initialize(display, &major, &minor)) {
        std::printf("SKIP: no EGL display could be initialised (%s, error 0x%x)\n", chosen.c_str(), egl.getError());
        return 77;
    }
    std::printf("EGL %d.%d on %s: vendor '%s', version '%s', client APIs '%s'\n", major, minor, chosen.c_str(),
                egl.queryString(display, EGL_VENDOR), egl.queryString(display, EGL_VERSION),
                egl.queryString(display, EGL_CLIENT_APIS));

    const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                    EGL_RED_SIZE,     8,               EGL_GREEN_SIZE,      8,
                                    EGL_BLUE_SIZE,    8,               EGL_ALPHA_SIZE,      8,
                                    EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!egl.bindApi(EGL_OPENGL_API) || !egl.chooseConfig(display, configAttribs, &config, 1, &configs) || configs < 1) {
        std::printf("SKIP: no desktop-OpenGL pbuffer config (error 0x%x)\n", egl.getError());
        egl.terminate(display);
        return 77;
    }
    const EGLint pbufferAttribs[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
    EGLSurface surface = egl.createPbufferSurface(display, config, pbufferAttribs);
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,       3, EGL_CONTEXT_MINOR_VERSION, 3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
    EGLContext context = egl.createContext(display, config, nullptr, contextAttribs);
    if (!context || !egl.makeCurrent(display, surface, surface, context)) {
        std::printf("SKIP: no OpenGL 3.3 core context (error 0x%x)\n", egl.getError());
        egl.terminate(display);
        return 77;
    }

    void* libGl = dlopen("libOpenGL.so.0", RTLD_NOW | RTLD_GLOBAL);
    if (!libGl) libGl = dlopen("libGL.so.1", RTLD_NOW | RTLD_GLOBAL);
    Gl gl;
    ok = load(gl.getString, libGl, gpa, "glGetString") && load(gl.getError, libGl, gpa, "glGetError") &&
         load(gl.genBuffers, libGl, gpa, "glGenBuffers") && load(gl.deleteBuffers, libGl, gpa, "glDeleteBuffers") &&
         load(gl.bindBuffer, libGl, gpa, "glBindBuffer") && load(gl.bufferData, libGl, gpa, "glBufferData") &&
         load(gl.getBufferSubData, libGl, gpa, "glGetBufferSubData") && load(gl.finish, libGl, gpa, "glFinish");
    if (!ok) {
        std::printf("SKIP: OpenGL entry points not found\n");
        return 77;
    }
    const char* renderer = reinterpret_cast<const char*>(gl.getString(GL_RENDERER));
    std::printf("GL: vendor '%s', renderer '%s', version '%s'\n", gl.getString(GL_VENDOR), renderer,
                gl.getString(GL_VERSION));
    const bool nvidiaGl = renderer && (std::strstr(renderer, "NVIDIA") || std::strstr(renderer, "H100") ||
                                       std::strstr(renderer, "H200"));

    trazo::CudaGlDisplay* interop = trazo::createCudaGlDisplay();
    if (haveCuda && nvidiaGl) {
        std::printf("Interop on an NVIDIA GL context (the path the viewer takes with --backend cuda):\n");
        const uint32_t w = 97, h = 61;  // 5917 pixels: not a multiple of the kernel's 256-thread blocks
        unsigned pbo = makeBuffer(gl, size_t(w) * h * 16);
        Outcome o = resolveAndCompare(gl, *interop, pbo, w, h, 1);
        check(o.resolved, "resolve 97x61 into a fresh PBO" + (o.resolved ? "" : ": " + o.why));
        if (o.resolved)
            check(o.bad == 0, "97x61 values equal sum/count (max error " + std::to_string(o.maxError) + ", " +
                                  std::to_string(o.bad) + " off)");
        o = resolveAndCompare(gl, *interop, pbo, w, h, 2);  // same buffer and size: map/unmap only
        check(o.resolved && o.bad == 0, "second resolve, same registration, new values" + (o.resolved ? "" : ": " + o.why));
        // The viewer's resize: release the registration, re-specify the PBO (glBufferData), resolve (registers).
        const uint32_t w2 = 640, h2 = 360;
        respecify(gl, *interop, pbo, size_t(w2) * h2 * 16);
        o = resolveAndCompare(gl, *interop, pbo, w2, h2, 3);
        check(o.resolved && o.bad == 0, "resize 97x61 -> 640x360 (release, glBufferData, register again)" +
                                            (o.resolved ? "" : ": " + o.why));
        respecify(gl, *interop, pbo, size_t(w) * h * 16);
        o = resolveAndCompare(gl, *interop, pbo, w, h, 4);
        check(o.resolved && o.bad == 0, "resize back to 97x61" + (o.resolved ? "" : ": " + o.why));
        // A buffer too small for the image: refused with a reason, nothing written.
        respecify(gl, *interop, pbo, 64);
        o = resolveAndCompare(gl, *interop, pbo, w2, h2, 5);
        check(!o.resolved && !o.why.empty(), "too-small buffer refused: '" + o.why + "'");
        gl.deleteBuffers(1, &pbo);
        // A name that is no GL buffer: registration fails, the error is cleared.
        o = resolveAndCompare(gl, *interop, 424242u, w, h, 6);
        check(!o.resolved && !o.why.empty(), "unknown buffer name refused: '" + o.why + "'");
        void* scratch = nullptr;
        const cudaError_t after = cudaMalloc(&scratch, 16);
        check(after == cudaSuccess && cudaGetLastError() == cudaSuccess, "CUDA still usable after the refusals");
        cudaFree(scratch);

        if (timing) {
            // Interop resolve versus the host path's readAccumulation copy, at 1920x1080.
            const uint32_t tw = 1920, th = 1080;
            unsigned big = makeBuffer(gl, size_t(tw) * th * 16);
            std::vector<float> expected;
            const std::vector<trazo::AccumPixel> host = makeAccum(tw, th, 7, expected);
            trazo::AccumPixel* device = nullptr;
            cudaMalloc(&device, host.size() * sizeof(trazo::AccumPixel));
            cudaMemcpy(device, host.data(), host.size() * sizeof(trazo::AccumPixel), cudaMemcpyHostToDevice);
            std::string why;
            trazo::resolveIntoGlBuffer(*interop, big, device, tw, th, why);  // registers
            const int reps = 20;
            auto t0 = std::chrono::steady_clock::now();
            bool all = true;
            for (int r = 0; r < reps; ++r) all = trazo::resolveIntoGlBuffer(*interop, big, device, tw, th, why) && all;
            gl.finish();
            const double interopMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / reps;
            std::vector<trazo::AccumPixel> back(host.size());
            t0 = std::chrono::steady_clock::now();
            for (int r = 0; r < reps; ++r)
                cudaMemcpy(back.data(), device, back.size() * sizeof(trazo::AccumPixel), cudaMemcpyDeviceToHost);
            const double copyMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / reps;
            std::printf("  timing 1920x1080: interop resolve %.3f ms/frame (%s); readAccumulation copy alone %.3f ms\n",
                        interopMs, all ? "all ok" : ("failed: " + why).c_str(), copyMs);
            cudaFree(device);
            gl.deleteBuffers(1, &big);
        }
    } else {
        std::printf("Interop on a GL context CUDA cannot share (%s GL, CUDA %s): must fail cleanly:\n",
                    nvidiaGl ? "NVIDIA" : "non-NVIDIA", haveCuda ? "present" : "absent");
        const uint32_t w = 33, h = 17;
        unsigned pbo = makeBuffer(gl, size_t(w) * h * 16);
        Outcome o = resolveAndCompare(gl, *interop, pbo, w, h, 1);
        check(!o.resolved && !o.why.empty(), "resolve refused with a reason: '" + o.why + "'");
        if (haveCuda) {
            void* scratch = nullptr;
            check(cudaMalloc(&scratch, 16) == cudaSuccess && cudaGetLastError() == cudaSuccess,
                  "CUDA still usable after the refusal");
            cudaFree(scratch);
        }
        gl.deleteBuffers(1, &pbo);
    }
    // No current context at all (a viewer thread without one): refused, no crash.
    egl.makeCurrent(display, nullptr, nullptr, nullptr);
    {
        trazo::CudaGlDisplay* bare = trazo::createCudaGlDisplay();
        trazo::AccumPixel* device = nullptr;
        if (haveCuda && cudaMalloc(&device, 64 * sizeof(trazo::AccumPixel)) != cudaSuccess) device = nullptr;
        if (device) cudaMemset(device, 0, 64 * sizeof(trazo::AccumPixel));
        std::string why;
        const bool resolved = trazo::resolveIntoGlBuffer(*bare, 1u, device, 8, 8, why);
        check(!resolved && !why.empty(), "no current GL context refused: '" + why + "'");
        trazo::destroyCudaGlDisplay(bare);
        if (device) cudaFree(device);
        cudaGetLastError();
    }
    egl.makeCurrent(display, surface, surface, context);
    trazo::destroyCudaGlDisplay(interop);  // unregisters while the context is still current, as the viewer does
    egl.makeCurrent(display, nullptr, nullptr, nullptr);
    egl.destroyContext(display, context);
    egl.terminate(display);
    std::printf("egl_interop_probe: %d checks, %d failed%s\n", checks, failures,
                haveCuda && nvidiaGl ? "" : " (no NVIDIA GL + CUDA pair here: only the refusal paths were checked)");
    return failures ? 1 : 0;
}
