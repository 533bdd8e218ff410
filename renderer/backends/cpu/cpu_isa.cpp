// Chooses the CPU backend's kernels (cpu_kernels.h) at start-up: the widest instruction set the CPU has, or
// the one TRAZO_CPU_ISA names.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

#include "backends/cpu/cpu_kernels.h"

namespace trazo {

const char* cpuIsaName(CpuIsa isa) {
    switch (isa) {
        case CpuIsa::Sse2: return "sse2";
        case CpuIsa::Avx2: return "avx2";
        case CpuIsa::Avx512: return "avx512";
    }
    return "?";
}

bool cpuIsaSupported(CpuIsa isa) {
#if TRAZO_CPU_ISA_X86
    // libgcc's checks include the OS's: XGETBV must show the YMM (and ZMM) state saved.
    switch (isa) {
        case CpuIsa::Sse2: return true;
        case CpuIsa::Avx2: return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
        case CpuIsa::Avx512:
            return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                   __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl") &&
                   cpuIsaSupported(CpuIsa::Avx2);
    }
    return false;
#else
    return isa == CpuIsa::Sse2;  // the baseline build only (named sse2 on every processor)
#endif
}

// nullptr where the CPU lacks the instruction set or this build has no kernels for it (TRAZO_CPU_ISAS).
const CpuKernels* cpuKernelsFor(CpuIsa isa) {
    if (!cpuIsaSupported(isa)) return nullptr;
    switch (isa) {
        case CpuIsa::Sse2: return &cpuKernelsSse2();
#if TRAZO_CPU_BUILD_AVX2
        case CpuIsa::Avx2: return &cpuKernelsAvx2();
#endif
#if TRAZO_CPU_BUILD_AVX512
        case CpuIsa::Avx512: return &cpuKernelsAvx512();
#endif
        default: break;
    }
    return nullptr;
}

const CpuKernels& selectCpuKernels() {
    const CpuKernels* widest = &cpuKernelsSse2();
    for (CpuIsa isa : kCpuIsas)
        if (const CpuKernels* k = cpuKernelsFor(isa)) widest = k;
    const char* forced = std::getenv("TRAZO_CPU_ISA");
    if (!forced || !*forced) return *widest;
    for (CpuIsa isa : kCpuIsas) {
        if (std::strcmp(forced, cpuIsaName(isa)) != 0) continue;
        if (const CpuKernels* k = cpuKernelsFor(isa)) return *k;
    }
    static std::once_flag warned;
    std::call_once(warned, [&] {
        std::fprintf(stderr, "trazo: TRAZO_CPU_ISA=%s is not an instruction set this CPU and build run (sse2, avx2, "
                             "avx512); using %s\n", forced, cpuIsaName(widest->isa));
    });
    return *widest;
}

}  // namespace trazo
