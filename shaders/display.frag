#version 330 core
// The display pass's fragment stage: the estimate (sum / count, linear RGB, row 0 = top of the image) shown
// in `imageRect` (x, y, width, height in framebuffer pixels, origin bottom-left), clipped to `areaRect`, with an
// exposure and one of three tone curves, and the selection's outline over it. Mode 0 at exposure 0 shows exactly what a PNG screenshot stores (the seed's
// round(255·clamp(c)), no gamma); the default framebuffer is not sRGB, so the value written is the byte shown.
uniform sampler2D estimate;
uniform vec4 imageRect;
uniform vec4 areaRect;        // the image's area beside the panel: nothing is drawn outside it
uniform sampler2D outline;    // R8, the image's size or another (a preview's): non-zero on the outline
uniform int hasOutline;
uniform float exposureScale;  // 2^stops
uniform int toneMode;         // 0: the seed's clamp, 1: sRGB, 2: filmic (ACES fit) then sRGB
uniform vec3 outsideColor;

out vec4 fragColor;

vec3 srgbFromLinear(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// Narkowicz's fit of the ACES filmic curve (2015).
vec3 filmic(vec3 c) {
    return clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
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
    c *= exposureScale;
    if (toneMode == 1) {
        c = srgbFromLinear(c);
    } else if (toneMode == 2) {
        c = srgbFromLinear(filmic(c));
    } else {
        // The PNG's byte, round(255·c) with halves up (image_writer.cpp), made here: GL's own conversion may
        // round halves to even (Mesa's llvmpipe does), a byte off on a flat 0.3.
        c = floor(255.0 * clamp(c, 0.0, 1.0) + 0.5) / 255.0;
    }
    fragColor = vec4(c, 1.0);
}
