// TRAZO_GL_CHECK: reports a GL error with the call's file:line (GL only, the viewer's code).
#pragma once

#include <glad/gl.h>

#include <cstdio>

namespace trazo {

inline bool reportGlError(const char* call, const char* file, int line) {
    bool ok = true;
    for (GLenum e; (e = glGetError()) != GL_NO_ERROR;) {
        std::fprintf(stderr, "%s:%d: %s: GL error 0x%04x\n", file, line, call, unsigned(e));
        ok = false;
    }
    return ok;
}

}  // namespace trazo

#define TRAZO_GL_CHECK(call) ((call), ::trazo::reportGlError(#call, __FILE__, __LINE__))
