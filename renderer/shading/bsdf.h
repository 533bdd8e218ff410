// The BSDF of SPEC §7 at one hit: eval, sample and pdf over a closed set of lobes, built per hit from the
// material (makeBsdf), as pbrt-v4's BxDF interface is, without virtual calls; host and device.
//
//   f = o·[(1 − a)·(f_d + f_s) + a·Ks·g_r] + (1 − o)·g_t
//
// diffuse f_d (Oren–Nayar with 1/π), glossy f_s (Beckmann with Smith's G1, microfacet.h), reflection g_r (the
// mirror, or §5's cone as a lobe) and transmission g_t (the smooth dielectric, or §6's cone about Snell's
// direction). The thesis's Shade (SPEC §5) reads the first two lobes differently and is not sampled:
// shading/thesis_brdf.h.
#pragma once

#include <cstdint>

#include "core/sin_cos.h"
#include "core/vec3.h"
#include "shading/scattering.h"
#include "shading/fresnel.h"
#include "shading/material.h"
#include "shading/microfacet.h"
#include "shading/oren_nayar.h"
#include "shading/shading_point.h"

namespace trazo {

enum BsdfLobe : uint32_t {
    kLobeDiffuse = 1u,
    kLobeGlossy = 2u,
    kLobeReflection = 4u,    // the mirror (delta) or the reflection cone
    kLobeTransmission = 8u,  // the dielectric (delta) or the transmission cone
};

struct BsdfSample {
    Vec3 wi;
    Vec3 weight;    // f·|n·wi| / pdf: what a path's throughput is multiplied by
    float pdf;      // in solid angle; for a delta lobe, the probability of having picked it
    uint32_t lobe;  // the BsdfLobe drawn
    bool delta;     // no other direction could have given wi: no MIS weight
    bool subsurface = false;  // the diffuse lobe of a scattering material: wi is not drawn, a walk follows
};

// The density of a direction at angle θ < halfAngle from the cone's axis with θ and φ uniform (SPEC §5's cones).
TRAZO_HD float conePdf(Vec3 axis, float halfAngle, Vec3 w) {
    const float c = minOf(dot(axis, w), 1.0f);
    const float sinTheta = sqrtf(maxOf(0.0f, 1.0f - c * c));
    const float theta = atan2f(sinTheta, c);
    if (!(theta < halfAngle) || !(sinTheta > 0.0f)) return 0.0f;
    return 1.0f / (halfAngle * 2.0f * kPi * sinTheta);
}

// A cosine-weighted direction about the frame's axis (Malley's method over a concentric disk).
TRAZO_HD Vec3 sampleCosineHemisphere(const ConeFrame& f, float u1, float u2) {
    const float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
    if (a == 0.0f && b == 0.0f) return f.axis;
    float r, phi;
    if (fabsf(a) > fabsf(b)) {
        r = a;
        phi = 0.25f * kPi * (b / a);
    } else {
        r = b;
        phi = 0.5f * kPi - 0.25f * kPi * (a / b);
    }
    const float x = r * cosf(phi), y = r * sinf(phi);
    const float z = sqrtf(maxOf(0.0f, 1.0f - x * x - y * y));
    return normalize(f.t1 * x + f.t2 * y + f.axis * z);
}

struct Bsdf {
    ConeFrame frame;  // about the shading normal n, which faces wo's side
    Vec3 ng;          // geometric normal on wo's side
    Vec3 diffuse, glossy, reflection;
    float transmission;  // 1 − o
    float sigma, m, reflectionHalfAngle, refractionHalfAngle;
    float eta;           // n_incident / n_transmitted for a transmitted direction
    bool fresnel;
    float ior;           // the material's index, for Fresnel on reflection
    float pick[4];       // the probability of each lobe, in BsdfLobe order
    // SPEC §7's subsurface scattering: the diffuse lobe is an index-matched medium below the surface, entered
    // by a walk (integrator/subsurface.h) rather than a direction; `diffuse` is then the lobe's weight.
    bool subsurface = false;

    TRAZO_HD Vec3 n() const { return frame.axis; }

    TRAZO_HD Vec3 mirror(Vec3 wo) const { return reflectDirection(-wo, n()); }
    TRAZO_HD float reflectionFresnel(Vec3 wo) const { return fresnel ? dielectricFresnel(dot(n(), wo), 1.0f, ior) : 1.0f; }
    TRAZO_HD bool refracted(Vec3 wo, Vec3& wt) const { return refractDirection(-wo, n(), eta, wt); }

    // f·|n·wi| summed over the lobes that are not delta.
    TRAZO_HD Vec3 evalCos(Vec3 wo, Vec3 wi) const {
        Vec3 f(0.0f);
        const bool above = dot(wi, ng) > 0.0f && dot(wi, n()) > 0.0f;
        if (above) {
            if (pick[0] > 0.0f && !subsurface) f += diffuse * (evalOrenNayar(n(), wi, wo, sigma) / kPi);
            if (pick[1] > 0.0f) {
                const float fr = fresnel ? dielectricFresnel(dot(wo, normalize(wo + wi)), 1.0f, ior) : 1.0f;
                f += glossy * (beckmannCos(n(), wo, wi, m) * fr);
            }
            if (pick[2] > 0.0f && reflectionHalfAngle > 0.0f)
                f += reflection * (reflectionFresnel(wo) * conePdf(mirror(wo), reflectionHalfAngle, wi));
        }
        Vec3 wt;
        if (pick[3] > 0.0f && refractionHalfAngle > 0.0f && dot(wi, ng) < 0.0f && refracted(wo, wt))
            f += Vec3(transmission * conePdf(wt, refractionHalfAngle, wi));
        return f;
    }

    // The density with which sample() draws wi, over the lobes that are not delta.
    TRAZO_HD float pdf(Vec3 wo, Vec3 wi) const {
        float p = 0.0f;
        const bool above = dot(wi, ng) > 0.0f && dot(wi, n()) > 0.0f;
        if (above) {
            if (pick[0] > 0.0f && !subsurface) p += pick[0] * dot(n(), wi) / kPi;
            if (pick[1] > 0.0f) p += pick[1] * beckmannPdf(n(), wo, wi, m);
            if (pick[2] > 0.0f && reflectionHalfAngle > 0.0f)
                p += pick[2] * conePdf(mirror(wo), reflectionHalfAngle, wi);
        }
        Vec3 wt;
        if (pick[3] > 0.0f && refractionHalfAngle > 0.0f && dot(wi, ng) < 0.0f && refracted(wo, wt))
            p += pick[3] * conePdf(wt, refractionHalfAngle, wi);
        return p;
    }

    // One direction from uLobe (which lobe) and (u1, u2); false where the draw carries nothing (a direction
    // below the surface for reflection, above it for transmission, or no lobe at all).
    TRAZO_HD bool sample(Vec3 wo, float uLobe, float u1, float u2, BsdfSample& out) const {
        uint32_t lobe = 0;
        float acc = 0.0f;
        while (lobe < 3 && uLobe >= acc + pick[lobe]) acc += pick[lobe++];
        if (!(pick[lobe] > 0.0f)) return false;
        out.lobe = 1u << lobe;
        out.delta = false;
        out.subsurface = false;
        if (lobe == 0 && subsurface) {
            out.subsurface = true;
            out.delta = true;
            out.pdf = pick[0];
            out.weight = diffuse / pick[0];
            out.wi = -n();
            return true;
        }
        if (lobe == 0) {
            out.wi = sampleCosineHemisphere(frame, u1, u2);
        } else if (lobe == 1) {
            const Vec3 h = sampleBeckmannNormal(n(), frame.t1, frame.t2, m, u1, u2);
            out.wi = reflectDirection(-wo, h);
        } else if (lobe == 2) {
            const Vec3 axis = mirror(wo);
            if (reflectionHalfAngle > 0.0f) {
                out.wi = directionInCone(axis, u1 * reflectionHalfAngle, 2.0f * kPi * u2);
            } else {
                out.wi = axis;
                out.delta = true;
                out.pdf = pick[2];
                out.weight = reflection * (reflectionFresnel(wo) / pick[2]);
                return dot(out.wi, ng) > 0.0f;
            }
        } else {
            return sampleTransmission(wo, u1, u2, out);
        }
        out.pdf = pdf(wo, out.wi);
        if (!(out.pdf > 0.0f)) return false;
        out.weight = evalCos(wo, out.wi) / out.pdf;
        return true;
    }

    // The dielectric: Fresnel's split (with `Fresnel 1`) by u1, Snell's direction or a cone about it by u1, u2.
    TRAZO_HD bool sampleTransmission(Vec3 wo, float u1, float u2, BsdfSample& out) const {
        Vec3 wt;
        const bool crosses = refracted(wo, wt);
        const float f = !crosses ? 1.0f : fresnel ? dielectricFresnel(dot(wo, n()), 1.0f, 1.0f / eta) : 0.0f;
        out.lobe = kLobeTransmission;
        if (u1 < f) {  // total internal reflection, or Fresnel's reflected share
            out.wi = mirror(wo);
            out.delta = true;
            out.pdf = pick[3] * f;
            out.weight = Vec3(transmission / pick[3]);
            return dot(out.wi, ng) > 0.0f;
        }
        if (refractionHalfAngle > 0.0f) {
            const float v = f < 1.0f ? (u1 - f) / (1.0f - f) : u1;  // u1 rescaled past Fresnel's share
            out.wi = directionInCone(wt, v * refractionHalfAngle, 2.0f * kPi * u2);
            out.delta = false;
            if (!(dot(out.wi, ng) < 0.0f)) return false;
            out.pdf = pick[3] * (1.0f - f) * conePdf(wt, refractionHalfAngle, out.wi);
            if (!(out.pdf > 0.0f)) return false;
            out.weight = Vec3(transmission / pick[3]);
            return true;
        }
        out.wi = wt;
        out.delta = true;
        out.pdf = pick[3] * (1.0f - f);
        out.weight = Vec3(transmission / pick[3]);
        return dot(out.wi, ng) < 0.0f;
    }
};

// The BSDF of material m at shading point sp (n and ng facing the viewer). entering: the viewer is outside the
// material's solid, so a transmitted direction goes from index 1 into RefractionIndex (else out of it).
TRAZO_HD Bsdf makeBsdf(const MaterialData& m, const ShadingPoint& sp, bool entering) {
    Bsdf b;
    b.frame = coneFrame(sp.n);
    b.ng = sp.ng;
    const float o = m.opacity, a = m.reflectionAmount;
    b.diffuse = m.diffuse * (o * (1.0f - a));
    b.glossy = m.specular * (o * (1.0f - a));
    b.reflection = m.specular * (o * a);
    b.transmission = 1.0f - o;
    b.sigma = m.roughness;
    b.m = maxOf(m.roughness, 0.01f);
    b.reflectionHalfAngle = m.reflectionHalfAngle;
    b.refractionHalfAngle = m.refractionHalfAngle;
    b.ior = m.refractionIndex;
    b.eta = entering ? 1.0f / m.refractionIndex : m.refractionIndex;
    b.fresnel = m.fresnel != 0u;
    const auto weight = [](Vec3 c) { return maxOf(0.0f, (c.x + c.y + c.z) * (1.0f / 3.0f)); };
    b.pick[0] = weight(b.diffuse);
    b.pick[1] = weight(b.glossy);
    b.pick[2] = weight(b.reflection);
    b.pick[3] = maxOf(0.0f, b.transmission);
    const float total = b.pick[0] + b.pick[1] + b.pick[2] + b.pick[3];
    for (float& p : b.pick) p = total > 0.0f ? p / total : 0.0f;
    return b;
}

}  // namespace trazo
