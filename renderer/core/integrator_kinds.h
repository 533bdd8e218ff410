// The integrators, one list: what a sample of a pixel converges to (SPEC §5–§6's model, §7's light transport).
// Each has its folder in integrator/ and a struct there (integrator/integrators.h) that names its kernel
// instances; a render's kind is RenderSettings::integrator.
#pragma once

#include <cstdint>

namespace trazo {

// X(Kind, Struct, "keyword"): the enumerator, the struct in integrator/<keyword>/, and the scene files' word.
#define TRAZO_INTEGRATORS(X) X(Thesis, ThesisIntegrator, "thesis") X(Path, PathIntegrator, "path")

enum class IntegratorKind : uint32_t {
#define TRAZO_X(kind, type, keyword) kind,
    TRAZO_INTEGRATORS(TRAZO_X)
#undef TRAZO_X
};

constexpr const char* kIntegratorKeywords[] = {
#define TRAZO_X(kind, type, keyword) keyword,
    TRAZO_INTEGRATORS(TRAZO_X)
#undef TRAZO_X
};
constexpr uint32_t kIntegratorCount = sizeof(kIntegratorKeywords) / sizeof(kIntegratorKeywords[0]);

}  // namespace trazo
