// Host only: up to 64 shadow rays from one origin (one shading point's block of area-light cells), or each from
// its own (the points that a shading point's indirect directions found, towards one point light), traced
// together through the top-level BVH, with a mask of the rays still in play per node, and spheres, boxes
// and cylinders tested against several rays at once (packet_lanes.h). Each ray's answer is occluded()'s bit for
// bit: a ray meets the same boxes (the slab test of intersectChildren, the same IEEE operations in the same
// order), so it reaches the same leaves, and the shapes' tests in lanes are their scalar tests' own template.
// Meshes and CSG solids take their scalar objectBlocks, ray by ray. aimShadowRays computes the rays of an
// area light's cells in the same lanes (integrator/thesis/direct_light_lanes.h, shadeCellsTogether).
#pragma once

#include "integrator/packets/packet_lanes.h"
#include "lights/rectangle.h"

namespace trazo {

namespace packet_detail {

// The rays of `live` that object o blocks. Origins: SharedOrigin or OwnOrigins (packet_lanes.h).
template <class Origins>
inline uint64_t objectBlocksPacket(const SceneView& scene, const ObjectRef& o, const Origins& origins,
                                   const RayPacket& rays, uint64_t live) {
    uint64_t blocked = 0;
    const auto add = [&](int g, uint64_t hits, LaneF, const LaneI*, const V3*) { blocked |= hits << (g * kLanes); };
    if (groupHits<false>(scene, o, origins, rays, live, add)) return blocked;  // any hit in (0, tMax) blocks
    // Meshes and CSG solids: their own scalar test, ray by ray.
    uint32_t entries[kTraversalStackSize];
    AnyStack stack{entries, kTraversalStackSize, 0};
    for (uint64_t m = live; m; m &= m - 1) {
        const int i = __builtin_ctzll(m);
        const Ray ray{origins.at(i), Vec3(rays.dx[i], rays.dy[i], rays.dz[i])};
        const bool blocks =
            visitObject(scene, o, [&](const auto& shape) { return objectBlocks(scene, shape, ray, rays.tMax[i], stack); });
        if (blocks) blocked |= 1ull << i;
    }
    return blocked;
}

}  // namespace packet_detail

// The shadow rays of shadeFromPoint towards points of a light's rectangle, lane by lane (see aimShadowRays).
struct AimedRays {
    uint64_t traced = 0;     // the rays shadeFromPoint sends (a light point at a distance, in front of n)
    uint64_t fromBelow = 0;  // those leaving from the origin below the surface (towards −ng)
};

// Ray k of `out` aims at the jittered point of the cell in column[k], row[k] of the rectangle's cellsU × cellsV
// grid, as cellPoint and shadeFromPoint compute it (lights/area_light.h, integrator/thesis/shade_from_point.h): the same operations in the same
// order, kPacketRays lanes of them, with cell k's two draws at rng dimensions dimension + 2k (u) and + 2k + 1
// (v) of the stream `key` (the caller moves its stream on by 2 per cell). p, n, ng: the shading point, its
// shading and geometric normals; above and below: its ray origins towards ±ng (ShadingPoint::rayOrigin).
inline AimedRays aimShadowRays(const RectangleShape& rect, uint32_t cellsU, uint32_t cellsV, const float* column,
                               const float* row, uint32_t key, uint32_t dimension, Vec3 p, Vec3 n, Vec3 ng,
                               Vec3 above, Vec3 below, RayPacket& out) {
    using namespace packet_detail;
    AimedRays aimed;
    const float width = float(cellsU), height = float(cellsV);
    LaneU lane;
    for (int i = 0; i < kLanes; ++i) lane[i] = uint32_t(i);
    for (int g = 0; g < kGroups; ++g) {
        const int o = g * kLanes;
        const LaneU draw = dimension + 2u * (uint32_t(o) + lane);
        const LaneF su = (load(column + o) + unitFloats(key, draw)) / width;
        const LaneF sv = (load(row + o) + unitFloats(key, draw + 1u)) / height;
        const LaneF a = 2.0f * su - 1.0f, b = 2.0f * sv - 1.0f;
        const V3 x = {rect.center.x + rect.halfU.x * a + rect.halfV.x * b,
                      rect.center.y + rect.halfU.y * a + rect.halfV.y * b,
                      rect.center.z + rect.halfU.z * a + rect.halfV.z * b};
        const V3 toLight = {x.x - p.x, x.y - p.y, x.z - p.z};
        const LaneF dist = sqrt(dot(toLight, toLight));
        const LaneF inv = 1.0f / dist;
        const V3 l = {toLight.x * inv, toLight.y * inv, toLight.z * inv};
        const LaneI traced = (dist > 0.0f) & ~(dot(n, l) <= 0.0f);
        const LaneI down = dot(ng, l) < 0.0f;
        const V3 toEnd = {x.x - (down ? splat(below.x) : splat(above.x)), x.y - (down ? splat(below.y) : splat(above.y)),
                          x.z - (down ? splat(below.z) : splat(above.z))};
        const LaneF tMax = sqrt(dot(toEnd, toEnd));
        std::memcpy(out.dx + o, &l.x, sizeof l.x);
        std::memcpy(out.dy + o, &l.y, sizeof l.y);
        std::memcpy(out.dz + o, &l.z, sizeof l.z);
        std::memcpy(out.tMax + o, &tMax, sizeof tMax);
        aimed.traced |= bits(traced) << o;
        aimed.fromBelow |= bits(down) << o;
    }
    return aimed;
}

namespace packet_detail {

template <class Origins>
inline uint64_t occludedPacketFrom(const SceneView& scene, const Origins& origins, const RayPacket& rays,
                                   uint64_t active) {
    if (scene.topNodes.count == 0 || !active) return 0;
    const InverseDirections inv = inverseDirections(rays);
    const WideBvhNode* nodes = scene.topNodes.data;
    PacketEntry stack[kBvhWidth * kMaxBvhDepth + 1];
    int size = 0;
    stack[size++] = {0u, active};
    uint64_t blocked = 0;
    while (size > 0) {
        const PacketEntry e = stack[--size];
        const uint64_t live = e.rays & ~blocked;
        if (!live) continue;
        if (bvhIsLeaf(e.ref)) {
            const uint32_t first = bvhLeafFirst(e.ref), end = first + bvhLeafCount(e.ref);
            for (uint32_t i = first; i < end; ++i) {
                const uint64_t left = live & ~blocked;
                if (!left) break;
                blocked |= objectBlocksPacket(scene, scene.objects[i], origins, rays, left);
            }
            continue;
        }
        const WideBvhNode& node = nodes[e.ref];
        uint64_t childRays[kBvhWidth];
        raysEnteringChildren(node, origins, inv, rays.tMax, live, childRays);
        for (int c = kBvhWidth - 1; c >= 0; --c)
            if (childRays[c]) stack[size++] = {node.child[c], childRays[c]};
    }
    return blocked & active;
}

}  // namespace packet_detail

// The rays of `active` (bit i: ray i of `rays`) that something blocks: occluded(scene, Ray{origin, ray i's
// direction}, ray i's tMax) for each, bit for bit.
inline uint64_t occludedPacket(const SceneView& scene, Vec3 origin, const RayPacket& rays, uint64_t active) {
    return packet_detail::occludedPacketFrom(scene, packet_detail::SharedOrigin{origin}, rays, active);
}

// The same for rays with origins of their own: occluded(scene, Ray{origin i, direction i}, tMax i).
inline uint64_t occludedPacket(const SceneView& scene, const RayOrigins& origins, const RayPacket& rays,
                               uint64_t active) {
    return packet_detail::occludedPacketFrom(scene, packet_detail::OwnOrigins{origins}, rays, active);
}

}  // namespace trazo
