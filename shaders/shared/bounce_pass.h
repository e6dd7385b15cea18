// The voxel bounce (vxgi/bounce.cpp, bounce.comp): bindings beside
// lib/cone_trace.glsl's, push constants, workgroup size, statistics layout;
// shared by C++ and GLSL.
#ifndef DVSGI_SHARED_BOUNCE_PASS_H
#define DVSGI_SHARED_BOUNCE_PASS_H

#include "common.h"
#include "voxel_data.h"

DVSGI_BEGIN

struct BouncePush {
    ConeParams cone;
    uvec4 flags;  // x 1 = write the per-workgroup change statistics (BIND_BOUNCE_STATS) (the ray normals' dispatch:
                  // 1 = --edge-voxels faces), y (clipmap) the voxels' level,
                  // z 1: a one-sided voxel a ray meets from behind shows it no light (the ray pass),
                  // w rays per voxel (the ray pass)
    // Temporal blending of the reflected light (BIND_BOUNCE_HISTORY): x this
    // frame's history tag (0 = no blending, nothing read or written), y the tag
    // a slot's history must carry to be blended with (last frame's), z the
    // blend weight of this frame's value (float bits).
    uvec4 blend;
};
DVSGI_CHECK_SIZE(BouncePush, 64);

// What each workgroup (VOXEL_LIST_GROUP list entries) writes when asked, at
// its flat group index: the sums over its voxels of |luminance change| and of
// the reflected part of the new luminance (two floats), so the host can tell
// when bounces have converged. Slots of groups not dispatched are zeroed before.
DVSGI_CONST(uint, BOUNCE_STATS_FLOATS, 2);

DVSGI_CONST(uint, BIND_BOUNCE_ACCUM, 3);
DVSGI_CONST(uint, BIND_BOUNCE_DIRECT, 4);     // direct light + emission (storage, read)
DVSGI_CONST(uint, BIND_BOUNCE_OUT, 5);        // radiance (storage, read for the change, then written)
DVSGI_CONST(uint, BIND_BOUNCE_STATS, 6);      // float[BOUNCE_STATS_FLOATS] per workgroup
DVSGI_CONST(uint, BIND_BOUNCE_LIST, 7);       // occupied-voxel list: one invocation per entry
DVSGI_CONST(uint, BIND_BOUNCE_GRID, 8);       // clipmap: the bounced level's own grid (BIND_CONE_GRID holds all levels)
// Per slot (slotTexel(slot, 0)), RGBA32UI: the light the slot's voxel
// reflected after last frame's bounce (x = rg, y = b, as half floats), z the
// world voxel it belonged to (packed, modulo 1024 per axis), w the frame tag
// it was written with.
DVSGI_CONST(uint, BIND_BOUNCE_HISTORY, 9);
DVSGI_CONST(uint, BIND_BOUNCE_SIDES, 10);  // per-slot side light (lib/voxel_sides.glsl): reads direct, writes reflected
// Rays (--bounce-trace rays): per slot, RG32UI, the light the voxel's rays
// gathered times its albedo (E rho / pi): a one-sided voxel's as half floats
// (x = rg, y = b), a two-sided voxel's favoured side's then its other side's
// as RGB9E5. Written by the ray pass, read by the shading pass after it.
DVSGI_CONST(uint, BIND_BOUNCE_TRACED, 11);
DVSGI_CONST(uint, BOUNCE_RAYS_SLOT_BYTES, 8);  // its texel
DVSGI_CONST(uint, BIND_BOUNCE_INDEX, 12);  // the slot index (voxel_data.h), read by the ray pass
// Rays: per slot, R32UI, the voxel's mean normal (lib/voxel_attributes.glsl's
// voxelNormal) in RAY_NORMAL_BITS per axis, written by a dispatch before the
// rays so that a ray meeting a voxel reads one word instead of its attribute
// channels. Steps of 1/RAY_NORMAL_SCALE; a normal that cancelled stays 0.
// Above the axes, with --edge-voxels faces: RAY_NORMAL_EXTENTS_BIT, the rays
// read the voxel's extents (voxel_data.h; the rays' passes bind them), and
// RAY_NORMAL_FACES_BIT where it shows its faces (lib/voxel_rays.glsl).
DVSGI_CONST(uint, BIND_BOUNCE_RAY_NORMALS, 13);
DVSGI_CONST(uint, BOUNCE_RAY_NORMAL_SLOT_BYTES, 4);  // its texel
DVSGI_CONST(uint, RAY_NORMAL_BITS, 10);
DVSGI_CONST(float, RAY_NORMAL_SCALE, 511.0);
DVSGI_CONST(uint, RAY_NORMAL_FACES_BIT, 1u << 30);
DVSGI_CONST(uint, RAY_NORMAL_EXTENTS_BIT, 1u << 31);
// Rays: which cells of 2, 4, 8 and 16 voxels per side hold an occupied
// voxel, one bit per cell (RAY_OCCUPANCY_LEVELS levels, level l's cells of
// 2^(l + 1) voxels, bit x + m (y + m z) from word rayOccupancyOffset(n, l),
// m = rayOccupancySide(n, l)), set by the dispatch that packs the normals
// from this frame's voxels, so that a ray crosses empty cells whole.
DVSGI_CONST(uint, BIND_BOUNCE_RAY_OCCUPANCY, 14);
DVSGI_CONST(uint, RAY_OCCUPANCY_LEVELS, 4);
DVSGI_FUNCTION uint rayOccupancySide(uint n, uint level) {
    uint m = n >> (level + 1u);
    return m > 0u ? m : 1u;
}
// Words before level `level`'s bits; at RAY_OCCUPANCY_LEVELS, all of them.
DVSGI_FUNCTION uint rayOccupancyOffset(uint n, uint level) {
    uint words = 0u;
    for (uint l = 0u; l < level; ++l) {
        uint m = rayOccupancySide(n, l);
        words += (m * m * m + 31u) / 32u;
    }
    return words;
}

// A voxel whose normal lies within about 11 degrees of an axis (this cosine)
// holds a floor or a wall: a plane across that axis, which rays reach at the
// plane through the voxel's centre (lib/voxel_rays.glsl). The mean normal of
// an edge, a corner or a tilted surface's staircase is no plane its voxel holds.
DVSGI_CONST(float, RAY_PLANE_AXIS_COS, 0.98);
DVSGI_FUNCTION float largestComponent(vec3 m) { return m.x > m.y ? (m.x > m.z ? m.x : m.z) : (m.y > m.z ? m.y : m.z); }
// The axis of m's largest component (ties: x before y before z).
DVSGI_FUNCTION int largestAxis(vec3 m) { return m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2); }
DVSGI_FUNCTION bool alongAnAxis(vec3 n) { return largestComponent(abs(n)) >= RAY_PLANE_AXIS_COS; }
// Where a voxel's rays (bounce.comp) start, from its centre along its normal
// n: VOXEL_RAY_START voxels along n's largest axis, just past the voxel's
// face there (an edge's or a corner's diagonal normal: past its faces along
// both or all three axes), unless another surface's voxel lies there
// (voxelRayStart in lib/voxel_rays.glsl). From a whole voxel along n, a
// floor's voxel gathered its light up to a voxel and a half above the floor,
// nearer a lit ceiling, and the Cornell box's second bounce came out 1 %
// bright. Exactly half a voxel put a point on the face itself, which floor()
// places in the voxel when n points down an axis: a thin wall's rays on that
// side started inside their own voxel, which they do not pass as their own
// surface, and met nothing (docs/quality.md, "Where a voxel's rays start").
DVSGI_CONST(float, VOXEL_RAY_START, 0.51);
DVSGI_FUNCTION vec3 voxelRayOrigin(vec3 centre, vec3 n) {
    return centre + n * (VOXEL_RAY_START / largestComponent(abs(n)));
}
// The rays' directions (lib/voxel_rays.glsl), shared with the tests' CPU
// march: the R2 sequence over the unit square, shifted per voxel by a hash.
// A pixel's rays start this far (voxels) before a surface that faces back
// toward it within their offset (lib/voxel_rays.glsl, pixelRayOffset).
DVSGI_CONST(float, RAY_GAP_MARGIN, 0.05);
// A sheet in the next voxel along a pixel's normal is another surface (not the
// pixel's own, voxelized into two layers) when it lies at least this far
// (voxels) in front of the pixel; a pixel's ray meets it where it crosses the
// sheet's plane at most this many voxels beside the pixel's voxel column
// (lib/voxel_rays.glsl, sheetAhead and meetsSheet).
DVSGI_CONST(float, RAY_SHEET_GAP, 0.25);
DVSGI_CONST(int, RAY_SHEET_REACH, 1);
DVSGI_CONST(float, RAY_R2_U, 0.7548776662);
DVSGI_CONST(float, RAY_R2_V, 0.5698402910);
DVSGI_FUNCTION uint rayHash(uint x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}
// Grid voxel v's shift (low 16 bits: u, high: v, in 1/65536).
DVSGI_FUNCTION uint raySeed(ivec3 v) { return rayHash(uint(v.x) | uint(v.y) << 10u | uint(v.z) << 20u); }
// The gather's rays (gather.comp's DVSGI_RAYS): trace pixel (x, y)'s shift,
// as raySeed's. Interleaved: the pixels of each GATHER_RAY_BLOCK^2 block take
// consecutive runs of `count` points of one R2 sequence, turned per block by
// a hash, so the neighbours that the resolve's filter averages have rays
// spread over the whole hemisphere (with a hash per pixel their sets
// overlapped by chance: the rooms' and the Cornell box's indirect light were
// 15-28 % noisier, docs/quality.md). Fixed point: uint arithmetic wraps
// modulo 2^32, which is the sequence's fract.
DVSGI_CONST(uint, GATHER_RAY_BLOCK, 4u);
DVSGI_CONST(uint, RAY_R2_U32, 3242174889u);  // RAY_R2_U * 2^32
DVSGI_CONST(uint, RAY_R2_V32, 2447445414u);  // RAY_R2_V * 2^32
DVSGI_FUNCTION uint gatherRaySeed(uint x, uint y, uint count) {
    uint k = x % GATHER_RAY_BLOCK + GATHER_RAY_BLOCK * (y % GATHER_RAY_BLOCK);
    uint turn = rayHash(x / GATHER_RAY_BLOCK | (y / GATHER_RAY_BLOCK) << 16u);
    uint u = (turn << 16u) + k * count * RAY_R2_U32;
    uint v = (turn & 0xffff0000u) + k * count * RAY_R2_V32;
    return u >> 16u | (v & 0xffff0000u);
}

// Clipmap: the levels' radiance atlas (vxgi/clipmap.h) as the last filtering
// left it, read for the change statistics: levels 1.. share one scratch
// radiance volume, cleared before each level's bounce, so it holds no "before".
DVSGI_CONST(uint, BIND_BOUNCE_LEVELS_BEFORE, 15);
// The rays read the voxels' extents (voxel_data.h).
DVSGI_CONST(uint, BIND_BOUNCE_EXTENTS, 16);

DVSGI_END

#endif
