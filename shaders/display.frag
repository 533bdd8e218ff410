#version 330 core
// The display pass's fragment stage: the estimate (sum / count, linear RGB, row 0 = top of the image) shown
// in `imageRect` (x, y, width, height in framebuffer pixels, origin bottom-left), clipped to `areaRect`, through
// SPEC §7's image transform (renderer/core/view_transform.h DisplayTransform::encode: 2^Exposure, clamp, the
// identity or sRGB's transfer function), with the selection's outline over it. Each pixel is the byte an 8-bit
// file stores, round(255·E(x)); the default framebuffer is not sRGB, so the value written is the byte shown.
uniform sampler2D estimate;
uniform vec4 imageRect;
uniform vec4 areaRect;        // the image's area beside the panel: nothing is drawn outside it
uniform sampler2D outline;    // R8, the image's size or another (a preview's): non-zero on the outline
uniform int hasOutline;
uniform float exposureScale;  // 2^Exposure
uniform int srgb;             // ViewTransform: 0 linear, 1 srgb (Auto resolved by the host)
uniform vec3 outsideColor;

out vec4 fragColor;

// DisplayTransform::encode: exposure, clamp (NaN to 0), then sRGB's transfer function when asked.
vec3 encode(vec3 c) {
    c *= exposureScale;
    c = mix(vec3(0.0), min(c, vec3(1.0)), greaterThan(c, vec3(0.0)));
    if (srgb == 0) return c;
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

// The texel under uv (origin bottom-left) of a texture stored top row first.
ivec2 texelAt(vec2 uv, ivec2 size) {
    return clamp(ivec2(floor(vec2(uv.x, 1.0 - uv.y) * vec2(size))), ivec2(0), size - 1);
}

void main() {
    vec2 uv = (gl_FragCoord.xy - imageRect.xy) / imageRect.zw;
    vec2 inArea = (gl_FragCoord.xy - areaRect.xy) / areaRect.zw;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))) ||
        any(lessThan(inArea, vec2(0.0))) || any(greaterThanEqual(inArea, vec2(1.0)))) {
        fragColor = vec4(outsideColor, 1.0);
        return;
    }
    if (hasOutline != 0 && texelFetch(outline, texelAt(uv, textureSize(outline, 0)), 0).r > 0.0) {
        fragColor = vec4(1.0, 0.55, 0.1, 1.0);
        return;
    }
    // Enlarged (1:1 included): the pixel itself, so that 1:1 shows exactly the saved image's values; reduced:
    // filtered.
    ivec2 size = textureSize(estimate, 0);
    vec3 c = imageRect.z >= float(size.x) ? texelFetch(estimate, texelAt(uv, size), 0).rgb
                                          : texture(estimate, vec2(uv.x, 1.0 - uv.y)).rgb;
    // The file's byte, round(255·E(x)) with halves up (image_writer.cpp), made here: GL's own conversion may
    // round halves to even (Mesa's llvmpipe does), a byte off on a flat 0.3.
    c = floor(255.0 * encode(c) + 0.5) / 255.0;
    fragColor = vec4(c, 1.0);
}
