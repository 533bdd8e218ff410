// Host only: the nearest object along each of up to 64 rays from one origin (a pinhole camera's rays through a
// block of pixels, a shading point's indirect directions), or each from its own (the indirect directions of a
// block's shading points), traced together through the top-level BVH, spheres,
// boxes and cylinders in SIMD lanes (packet_lanes.h). A ray's answer is intersectScene's object part bit for
// bit. Why it is: an object's hit t is its nearest root in (0, ∞) whatever the bound it is tested with, so the
// scalar traversal, which prunes only what cannot hold anything nearer than its running bound, returns the object
// of least t; so does this one, whose bound per ray is never below that least t. Only the order of visits
// differs, and with it the winner of a tie (two objects at the same t): those rays, and any that reach a mesh or
// CSG solid, are left to the scalar intersectScene (NearestHits::redo); tracePacket completes every answer to
// intersectScene's.
#pragma once

#include "integrator/packets/packet_lanes.h"

namespace trazo {

struct NearestHits {
    uint32_t object[kPacketRays];  // index into SceneView::objects, or kNoObject (none, or redo)
    float t[kPacketRays];
    uint8_t boxFace[kPacketRays];  // where the object is a box: boxHits' face
    float nx[kPacketRays], ny[kPacketRays], nz[kPacketRays];  // where it is a sphere: the hit's normal
    uint64_t redo = 0;  // the rays whose answer intersectScene must give
};

namespace packet_detail {

// nextafterf(t, INFINITY) for a finite t > 0 (a hit's t).
inline float nextFloatUp(float t) {
    uint32_t b;
    std::memcpy(&b, &t, sizeof b);
    ++b;
    std::memcpy(&t, &b, sizeof t);
    return t;
}

// Lane by lane: the rays of `hits` found object `index` at tHit (≤ their bound); the nearer replaces the best,
// an equal one is a tie. bound[i] stays just above ray i's best t, so that an object at that very t is seen.
inline void takeNearer(uint64_t hits, int offset, LaneF tHit, const LaneI* boxFace, const V3* normal,
                       uint32_t index, NearestHits& out, float* bound, uint64_t& ties) {
    for (uint64_t m = hits; m; m &= m - 1) {
        const int lane = __builtin_ctzll(m), i = offset + lane;
        const float t = tHit[lane];
        if (t < out.t[i]) {
            out.t[i] = t;
            out.object[i] = index;
            if (boxFace) out.boxFace[i] = (uint8_t)(*boxFace)[lane];
            if (normal) out.nx[i] = normal->x[lane], out.ny[i] = normal->y[lane], out.nz[i] = normal->z[lane];
            bound[i] = nextFloatUp(t);
            ties &= ~(1ull << i);
        } else {
            ties |= 1ull << i;
        }
    }
}

// Object `index` against the rays of `live`. Origins: SharedOrigin or OwnOrigins (packet_lanes.h).
template <class Origins>
inline void nearestOfObject(const SceneView& scene, uint32_t index, const Origins& origins, RayPacket& rays,
                            uint64_t live, NearestHits& out, uint64_t& ties) {
    const auto take = [&](int g, uint64_t hits, LaneF tHit, const LaneI* face, const V3* normal) {
        takeNearer(hits, g * kLanes, tHit, face, normal, index, out, rays.tMax, ties);
    };
    // Meshes and CSG solids: the rays that reach one are traced by the scalar code.
    if (!groupHits<true>(scene, scene.objects[index], origins, rays, live, take)) out.redo |= live;
}

template <class Origins>
inline void nearestPacketFrom(const SceneView& scene, const Origins& origins, RayPacket& rays, uint64_t active,
                              NearestHits& out) {
    for (int i = 0; i < kPacketRays; ++i) {
        out.object[i] = kNoObject;
        out.t[i] = INFINITY;
    }
    out.redo = 0;
    if (scene.topNodes.count == 0 || !active) return;
    const InverseDirections inv = inverseDirections(rays);
    const WideBvhNode* nodes = scene.topNodes.data;
    PacketEntry stack[kBvhWidth * kMaxBvhDepth + 1];
    int size = 0;
    stack[size++] = {0u, active};
    uint64_t ties = 0;
    while (size > 0) {
        const PacketEntry e = stack[--size];
        const uint64_t live = e.rays & ~out.redo;
        if (!live) continue;
        if (bvhIsLeaf(e.ref)) {
            const uint32_t first = bvhLeafFirst(e.ref), end = first + bvhLeafCount(e.ref);
            for (uint32_t i = first; i < end; ++i) nearestOfObject(scene, i, origins, rays, live & ~out.redo, out, ties);
            continue;
        }
        const WideBvhNode& node = nodes[e.ref];
        uint64_t childRays[kBvhWidth];
        raysEnteringChildren(node, origins, inv, rays.tMax, live, childRays);
        // Nearer children later on the stack, so that they are visited first and tighten the bounds: ordered
        // by the entry distance of their boxes' centres along the packet's first ray.
        const int first = __builtin_ctzll(live);
        const Vec3 d(rays.dx[first], rays.dy[first], rays.dz[first]), origin = origins.at(first);
        float key[kBvhWidth];
        int order[kBvhWidth];
        int count = 0;
        for (int c = 0; c < kBvhWidth; ++c) {
            if (!childRays[c]) continue;
            const Vec3 centre(node.bounds[0][0][c] + node.bounds[0][1][c], node.bounds[1][0][c] + node.bounds[1][1][c],
                              node.bounds[2][0][c] + node.bounds[2][1][c]);
            const float k = dot(centre * 0.5f - origin, d);
            int j = count++;
            for (; j > 0 && key[j - 1] < k; --j) key[j] = key[j - 1], order[j] = order[j - 1];
            key[j] = k;
            order[j] = c;
        }
        for (int j = 0; j < count; ++j) stack[size++] = {node.child[order[j]], childRays[order[j]]};
    }
    out.redo |= ties & active;
    for (uint64_t m = out.redo; m; m &= m - 1) out.object[__builtin_ctzll(m)] = kNoObject;
}

template <class Origins>
inline void tracePacketFrom(const SceneView& scene, const Origins& origins, RayPacket& rays, uint64_t active,
                            TracedRay* out) {
    NearestHits nearest;
    nearestPacketFrom(scene, origins, rays, active, nearest);
    uint32_t faceObject = kNoObject;  // the box face whose normal was computed last: most rays of a block share it
    int lastFace = -1;
    Vec3 faceNormal;
    for (uint64_t m = active; m; m &= m - 1) {
        const int i = __builtin_ctzll(m);
        const Ray ray{origins.at(i), Vec3(rays.dx[i], rays.dy[i], rays.dz[i])};
        TracedRay& c = out[i];
        c.ray = ray;
        const uint32_t object = nearest.object[i];
        const ObjectKind kind = object != kNoObject ? scene.objects[object].kind : ObjectKind::Sphere;
        // Ties, and the rays whose nearest object is a cylinder (the lanes keep no cylinder normal), take
        // intersectScene whole.
        if ((nearest.redo & (1ull << i)) || (kind != ObjectKind::Box && kind != ObjectKind::Sphere)) {
            c.found = intersectScene(scene, ray, INFINITY, c.hit);
            continue;
        }
        float tMax = INFINITY;
        c.found = false;
        if (object != kNoObject) {
            const ObjectRef& o = scene.objects[object];
            ShapeHit h{};
            if (o.kind == ObjectKind::Box) {  // intersectBox's normal of the face the lanes found
                const int face = nearest.boxFace[i];
                if (object != faceObject || face != lastFace) {
                    faceNormal = boxFaceNormal(scene.boxes[o.index], face >> 1, face & 1 ? 1.0f : -1.0f);
                    faceObject = object;
                    lastFace = face;
                }
                h.t = nearest.t[i];
                h.normal = faceNormal;
                h.triangle = uint32_t(face);
            } else {  // a sphere: the lanes computed intersectSphere's normal
                h.t = nearest.t[i];
                h.normal = Vec3(nearest.nx[i], nearest.ny[i], nearest.nz[i]);
            }
            c.hit = SurfaceHit{h.t, h.normal, object, 0, h.triangle, h.b1, h.b2};
            tMax = h.t;
            c.found = true;
        }
        if (intersectAreaLights(scene, ray, tMax, c.hit)) c.found = true;
    }
}

}  // namespace packet_detail

// The nearest object of each ray of `active` (bit i: ray i, tMax[i] = INFINITY on entry; used as the running
// bound), as intersectScene finds it, or kNoObject; rays in out.redo have no answer here.
inline void nearestPacket(const SceneView& scene, Vec3 origin, RayPacket& rays, uint64_t active, NearestHits& out) {
    packet_detail::nearestPacketFrom(scene, packet_detail::SharedOrigin{origin}, rays, active, out);
}

// The rays of `active` in `rays` (directions; tMax INFINITY, overwritten) from `origin`: out[i] is ray i and
// intersectScene(scene, ray i, INFINITY)'s answer.
inline void tracePacket(const SceneView& scene, Vec3 origin, RayPacket& rays, uint64_t active, TracedRay* out) {
    packet_detail::tracePacketFrom(scene, packet_detail::SharedOrigin{origin}, rays, active, out);
}

// The same for rays with origins of their own: out[i] is Ray{origin i, direction i} and its answer.
inline void tracePacket(const SceneView& scene, const RayOrigins& origins, RayPacket& rays, uint64_t active,
                        TracedRay* out) {
    packet_detail::tracePacketFrom(scene, packet_detail::OwnOrigins{origins}, rays, active, out);
}

}  // namespace trazo
