// Display: PBO → texture → full-screen triangle with the display-transform shader (GL 3.3 core).
#include "view/display.h"

#include <algorithm>

#include "display_shaders.h"
#include "view/gl_check.h"

namespace trazo {
namespace {

// The viewer's background: behind the panels and around the image (linear RGB, written to the framebuffer as is).
constexpr float kBackground[3] = {0.11f, 0.11f, 0.12f};

// "what: " and GL's info log of a shader that did not compile or a program that did not link.
std::string infoLog(const char* what, GLuint object, bool program) {
    char log[2048] = {};
    if (program) glGetProgramInfoLog(object, sizeof log, nullptr, log);
    else glGetShaderInfoLog(object, sizeof log, nullptr, log);
    return std::string(what) + ": " + log;
}

GLuint compileShader(GLenum kind, const char* source, std::string& error) {
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        error = infoLog(kind == GL_VERTEX_SHADER ? "display.vert" : "display.frag", shader, false);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

}  // namespace

const char* displayPathName(DisplayPath path) {
    switch (path) {
        case DisplayPath::Interop: return "CUDA-GL interop";
        case DisplayPath::Host: return "host-filled PBO";
        case DisplayPath::None: break;
    }
    return "none yet";
}

Display::~Display() {
    if (pbo_) glDeleteBuffers(1, &pbo_);
    if (outline_) glDeleteTextures(1, &outline_);
    if (texture_) glDeleteTextures(1, &texture_);
    if (vao_) glDeleteVertexArrays(1, &vao_);
    if (program_) glDeleteProgram(program_);
}

bool Display::init(std::string& error) {
    const GLuint vs = compileShader(GL_VERTEX_SHADER, shaders::kDisplayVert, error);
    if (!vs) return false;
    const GLuint fs = compileShader(GL_FRAGMENT_SHADER, shaders::kDisplayFrag, error);
    if (!fs) {
        glDeleteShader(vs);
        return false;
    }
    program_ = glCreateProgram();
    glAttachShader(program_, vs);
    glAttachShader(program_, fs);
    glLinkProgram(program_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
        error = infoLog("display shaders", program_, true);
        return false;
    }
    uImageRect_ = glGetUniformLocation(program_, "imageRect");
    uAreaRect_ = glGetUniformLocation(program_, "areaRect");
    uOutline_ = glGetUniformLocation(program_, "outline");
    uHasOutline_ = glGetUniformLocation(program_, "hasOutline");
    uExposure_ = glGetUniformLocation(program_, "exposureScale");
    uSrgb_ = glGetUniformLocation(program_, "srgb");
    uOutside_ = glGetUniformLocation(program_, "outsideColor");
    uEstimate_ = glGetUniformLocation(program_, "estimate");

    glGenVertexArrays(1, &vao_);  // core profile: a draw needs a bound VAO, even without attributes
    glGenBuffers(1, &pbo_);
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);  // enlarged pixels stay sharp
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glGenTextures(1, &outline_);
    glBindTexture(GL_TEXTURE_2D, outline_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (!reportGlError("Display::init", __FILE__, __LINE__)) {
        error = "OpenGL refused the display's objects";
        return false;
    }
    return true;
}

void Display::allocate(uint32_t width, uint32_t height) {
    width_ = width;
    height_ = height;
    const size_t bytes = size_t(width) * height * 4 * sizeof(float);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo_);
    TRAZO_GL_CHECK(glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(bytes), nullptr, GL_STREAM_DRAW));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    TRAZO_GL_CHECK(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, GLsizei(width), GLsizei(height), 0, GL_RGBA, GL_FLOAT, nullptr));
    glBindTexture(GL_TEXTURE_2D, 0);
}

bool Display::fillFromHost(Backend& backend) {
    backend.readAccumulation(accum_);
    const size_t pixels = size_t(width_) * height_;
    if (accum_.size() != pixels) return false;
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo_);
    auto* rgba = static_cast<float*>(glMapBufferRange(GL_PIXEL_UNPACK_BUFFER, 0, GLsizeiptr(pixels * 4 * sizeof(float)),
                                                      GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT));
    if (!rgba) {
        reportGlError("glMapBufferRange", __FILE__, __LINE__);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        return false;
    }
    for (size_t i = 0; i < pixels; ++i) {
        const Vec3 c = accum_[i].estimate();
        rgba[4 * i + 0] = c.x;
        rgba[4 * i + 1] = c.y;
        rgba[4 * i + 2] = c.z;
        rgba[4 * i + 3] = 1.0f;
    }
    glUnmapBuffer(GL_PIXEL_UNPACK_BUFFER);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    return true;
}

void Display::update(Backend& backend, uint32_t width, uint32_t height) {
    if (width != width_ || height != height_) {
        backend.releaseGlBuffer();  // the pixel buffer's store is about to change: no interop registration on it
        allocate(width, height);
    }
    bool filled = false;
    if (interopFailedFor_ != &backend) {
        std::string why;
        filled = backend.resolveToGlBuffer(pbo_, width, height, why);
        if (filled) {
            path_ = DisplayPath::Interop;
        } else {
            interopFailedFor_ = &backend;  // do not try again for this backend: the host path from now on
            interopFailure_ = why;
        }
    }
    if (!filled) {
        if (!fillFromHost(backend)) return;
        path_ = DisplayPath::Host;
    }
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    TRAZO_GL_CHECK(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, GLsizei(width), GLsizei(height), GL_RGBA, GL_FLOAT, nullptr));
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

void Display::setOutline(const std::vector<uint8_t>& mask, uint32_t width, uint32_t height) {
    hasOutline_ = !mask.empty() && mask.size() == size_t(width) * height;
    if (!hasOutline_) return;
    glBindTexture(GL_TEXTURE_2D, outline_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    TRAZO_GL_CHECK(glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, GLsizei(width), GLsizei(height), 0, GL_RED, GL_UNSIGNED_BYTE,
                                mask.data()));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void Display::draw(int framebufferWidth, int framebufferHeight, const ImageRect& area, const ImageRect& rect,
                   const DisplayTransform& transform) const {
    // The shader has gl_FragCoord from the bottom-left; the rectangles come from the top-left.
    const auto flipped = [&](const ImageRect& r) { return float(framebufferHeight) - r.y - r.height; };
    glViewport(0, 0, framebufferWidth, framebufferHeight);
    glClearColor(kBackground[0], kBackground[1], kBackground[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(program_);
    glUniform4f(uImageRect_, rect.x, flipped(rect), std::max(rect.width, 1.0f), std::max(rect.height, 1.0f));
    glUniform4f(uAreaRect_, area.x, flipped(area), area.width, area.height);
    glUniform1f(uExposure_, transform.scale);
    glUniform1i(uSrgb_, transform.srgb ? 1 : 0);
    glUniform3f(uOutside_, kBackground[0], kBackground[1], kBackground[2]);
    glUniform1i(uEstimate_, 0);
    glUniform1i(uOutline_, 1);
    glUniform1i(uHasOutline_, hasOutline_ ? 1 : 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, outline_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUseProgram(0);
}

}  // namespace trazo
