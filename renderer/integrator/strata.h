// The stratified grids of SPEC §5 (antialiasing positions, area-light cells, indirect directions, glossy
// cones) and which of their strata a pass evaluates. A pass takes one *block* of each grid at every hit it
// reaches: a grid of N strata in blocks of b (b | N) has P = N/b blocks, and pass v evaluates block
// σ(v mod P), σ a permutation drawn per pixel and per grid. Every P consecutive passes therefore visit every
// stratum once, and the rays above a grid (the camera ray, the reflected, refracted and indirect rays) are
// traced once per block instead of once per stratum — the thesis's own nesting. Blocks of 1 are the plain
// progressive render; blocks covering every grid are the thesis's estimator (--fixed-grid).
#pragma once

#include <cstdint>

#include "core/rng.h"

namespace trazo {

// Grid identities within a shading point's key (hashCombine(node, grid)).
constexpr uint32_t kGridGlossy = 1;
constexpr uint32_t kGridIndirect = 2;
constexpr uint32_t kGridGlossyTransmission = 3;
constexpr uint32_t kGridDispersionChannel = 4;  // the colour channel a dispersing ray carries on (SPEC §6)
constexpr uint32_t kGridAreaLightBase = 16;  // + light index
constexpr uint32_t kGridAntialiasing = 0x41414141u;
constexpr uint32_t kGridLens = 0x4c454e53u;  // the thin lens's rings × sectors (SPEC §6)

// The pixel's sample tree: the camera ray is its root, and each ray a shading point sends on (or the points Q
// its indirect rays find) is the child node hashCombine(node, branch), so every ray's grids draw their own strata.
constexpr uint32_t kSampleTreeRoot = 1;
constexpr uint32_t kBranchReflected = 1;
constexpr uint32_t kBranchRefractedIn = 2;   // into a transparent solid
constexpr uint32_t kBranchRefractedOut = 3;  // out of it, or reflected inside it
constexpr uint32_t kBranchIndirect = 4;      // the points Q of the indirect rays (their own light strata)
constexpr uint32_t kBranchSubsurface = 5;    // where a subsurface walk leaves its object (SPEC §6)

constexpr uint32_t kWholeGrid = 0xffffffffu;

// The block size a pass asks of each kind of grid. A value is a target: a grid of N strata uses the
// largest divisor of N that is at most the target (blockFor), so one value fits grids of every size.
// Glossy cones stay one stratum per pass: a block of them would multiply the pending rays of every bounce.
struct StrataBlocks {
    uint32_t antialiasing = 1;     // camera-ray positions per pixel and pass
    uint32_t areaLight = 1;        // cells of each area light at a camera-path shading point
    uint32_t indirect = 1;         // indirect directions at a camera-path shading point
    uint32_t lightAtIndirect = 1;  // cells of each area light at the point Q an indirect ray finds

    static constexpr StrataBlocks ones() { return StrataBlocks{}; }
    static constexpr StrataBlocks whole() { return StrataBlocks{kWholeGrid, kWholeGrid, kWholeGrid, kWholeGrid}; }
    constexpr bool operator==(const StrataBlocks& o) const {  // kernel headers stay within C++17: no = default
        return antialiasing == o.antialiasing && areaLight == o.areaLight && indirect == o.indirect &&
               lightAtIndirect == o.lightAtIndirect;
    }
};

// The largest divisor of count that is at most target (≥ 1): a block that tiles the grid exactly. No search
// for a whole grid, a block of 1 or a target that divides the grid (every block headlessBlocks chooses);
// otherwise at most about 2·√count steps, however the target sits against the grid's divisors (a search
// down from the target alone would take target − 1 steps for a prime grid: ~10⁶ per shading point for a
// `--blocks` target near a 2^20-cell light). The divisors pair as (d, count/d) with d ≤ √count: for a target
// at or above √count the answer is count/d for the least such d ≥ count/target if there is one, else the
// largest divisor below √count; for a smaller target it is the largest divisor at most the target.
// A count of 0 (a wrapped product, which the scene's bounds exclude) gives 1.
TRAZO_HD uint32_t blockFor(uint32_t count, uint32_t target) {
    if (target >= count) return count > 0u ? count : 1u;
    if (target <= 1u) return 1u;
    if (count % target == 0u) return target;
    uint32_t b = target;
    if (uint64_t(target) * target >= count) {
        uint32_t d = uint32_t((uint64_t(count) + target - 1u) / target);  // count/d ≤ target
        for (; uint64_t(d) * d <= count; ++d)
            if (count % d == 0u) return count / d;
        b = d - 1u;  // ⌊√count⌋: nothing between count/target and √count divides count
    }
    while (count % b != 0u) --b;
    return b;
}

// The strata of one grid a pass evaluates: stratum(j) for j ∈ [0, size). The grid's count/size blocks are
// the residues modulo count/size (block o holds o, o + P, o + 2P, …), so each block spreads over the whole
// grid, and a pass's block is drawn by one permutation of the P blocks rather than one per stratum.
struct StrataBlock {
    uint32_t offset;  // the block this pass takes, in [0, blocks)
    uint32_t blocks;  // count / size: the passes of the grid's cycle
    uint32_t size;
    TRAZO_HD uint32_t stratum(uint32_t j) const { return offset + j * blocks; }
    // Host lanes: the column and row, in a grid `width` strata wide, of strata first … first + count − 1 as
    // floats, stepped by `blocks` without a division per stratum; zeros from count up to padTo.
    void gridCells(uint32_t first, uint32_t count, uint32_t width, uint32_t padTo, float* column, float* row) const {
        const uint32_t stepColumn = blocks % width, stepRow = blocks / width;
        uint32_t c = stratum(first) % width, r = stratum(first) / width;
        for (uint32_t k = 0; k < count; ++k) {
            column[k] = float(c);
            row[k] = float(r);
            c += stepColumn;
            r += stepRow;
            if (c >= width) c -= width, ++r;
        }
        for (uint32_t k = count; k < padTo; ++k) column[k] = row[k] = 0.0f;
    }
};

// Identifies the grids of one shading point in the pixel's sample tree.
struct StrataKey {
    uint32_t seed, pixelIndex, pass, node;

    // Block pass mod P of the grid's P blocks, in an order drawn per pixel and per grid (stratumForPass).
    // `rotation` shifts the order: the points Q of one pass's indirect directions share a key, and direction j
    // takes the block j places on, so in one pass they take different blocks (stratified across the
    // directions) while each still visits every block once per P passes.
    TRAZO_HD StrataBlock block(uint32_t grid, uint32_t count, uint32_t target, uint32_t rotation = 0) const {
        const uint32_t size = blockFor(count, target);
        const uint32_t blocks = count / size;  // 0 only for a wrapped count of 0: one block, stratum 0
        if (blocks <= 1u) return StrataBlock{0u, 1u, size};
        const uint32_t first = stratumForPass(seed, pixelIndex, hashCombine(node, grid), pass, blocks);
        return StrataBlock{(first + rotation % blocks) % blocks, blocks, size};
    }
    // One stratum of a grid per pass (glossy cones).
    TRAZO_HD uint32_t stratum(uint32_t grid, uint32_t count) const { return block(grid, count, 1u).stratum(0); }
    TRAZO_HD StrataKey child(uint32_t branch) const { return StrataKey{seed, pixelIndex, pass, hashCombine(node, branch)}; }
};

// The antialiasing grid is k×k sub-pixel positions (SPEC §5 Pixel).
TRAZO_HD uint32_t antialiasingSide(uint32_t antialiasing) { return antialiasing >= 16 ? 4u : (antialiasing >= 4 ? 2u : 1u); }

// The passes after which a grid of `count` strata in blocks of `target` has visited every stratum once.
TRAZO_HD uint32_t blockPasses(uint32_t count, uint32_t target) { return count / blockFor(count, target); }

}  // namespace trazo
