// The voxel grid and its volumes, shared by C++ and GLSL.
//
// Voxel attributes live per slot, not per grid voxel: only occupied voxels
// have one. A uint index buffer over the N^3 grid holds each voxel's
// slot + 1 (0 = empty) and VOXEL_INDEX_STATIC; slot s is also entry s of the
// occupied-voxel list (shared/voxel_list_pass.h). The attributes are
// accumulated, not averaged in place: an R32_SFLOAT 3D image of
// VOXEL_SLOT_ROW x rows x VOXEL_CHANNELS texels holds channel c of slot s at
// (s % ROW, s / ROW, c). Fragments add into them with float atomics, so
// nothing saturates, nothing is dropped, and HDR emission survives. Readers
// divide by the fragment count (channel CH_COUNT) to get averages.
#ifndef DVSGI_SHARED_VOXEL_DATA_H
#define DVSGI_SHARED_VOXEL_DATA_H

#include "common.h"

DVSGI_BEGIN

DVSGI_CONST(uint, CH_ALBEDO_R, 0);
DVSGI_CONST(uint, CH_ALBEDO_G, 1);
DVSGI_CONST(uint, CH_ALBEDO_B, 2);
DVSGI_CONST(uint, CH_COUNT, 3);       // fragments that landed in the voxel
DVSGI_CONST(uint, CH_EMISSION_R, 4);  // W m^-2 sr^-1, summed
DVSGI_CONST(uint, CH_EMISSION_G, 5);
DVSGI_CONST(uint, CH_EMISSION_B, 6);
// Normal weights per axis and sign: sum of n_a^2 over fragments whose normal
// has n_a > 0 (POS) or n_a < 0 (NEG). A voxel holding a thin wall's two
// opposite faces keeps both orientations instead of averaging them to zero.
DVSGI_CONST(uint, CH_NORMAL_POS_X, 7);
DVSGI_CONST(uint, CH_NORMAL_NEG_X, 8);
DVSGI_CONST(uint, CH_NORMAL_POS_Y, 9);
DVSGI_CONST(uint, CH_NORMAL_NEG_Y, 10);
DVSGI_CONST(uint, CH_NORMAL_POS_Z, 11);
DVSGI_CONST(uint, CH_NORMAL_NEG_Z, 12);
// The normals' first moment, sum of n over fragments. Its length against the
// second moment's tells one plane (at any angle) from faces along several
// axes, an edge or a corner, which the weights above cannot: a plane at 45
// degrees and two faces at right angles have the same n_a^2 sums
// (lib/voxel_attributes.glsl, voxelPlaneShare).
DVSGI_CONST(uint, CH_FIRST_X, 13);
DVSGI_CONST(uint, CH_FIRST_Y, 14);
DVSGI_CONST(uint, CH_FIRST_Z, 15);
DVSGI_CONST(uint, VOXEL_CHANNELS, 16);
// A one-sided voxel less than this share one plane shows its faces
// (--edge-voxels faces; lib/voxel_attributes.glsl, voxelShowsFaces).
DVSGI_CONST(float, FACES_BELOW_PLANE_SHARE, 0.99);
// A one-sided voxel of plane share below this (its normals' first moment no
// longer than faces along the axes give: an edge or corner of axis faces, or
// a fold tilted a little off the axes) is lit face by face in the default
// voxel light too, and shows the lesser of that and Lambert with its mean
// normal (inject.comp, axisFaces).
DVSGI_CONST(float, AXIS_FACES_BELOW_PLANE_SHARE, 0.05);

// The part of its voxel a surface covers (where the voxel light looks a
// floor's or a wall's shadow map up; the rays at thin walls' ends; --edge-voxels
// faces). Per slot, one
// uint in the extents buffer (VOXEL_EXTENTS_BLOCK): per axis a (bits 8a to
// 8a + 7) bit k is set when a triangle that gave the voxel a sample has its
// bounding box reach [k/8, (k+1)/8) of the voxel along a. The compute and
// geometry-shader voxelizers OR them in; the pv voxelizer, which sees pixels,
// not triangles, leaves 0, read as the whole voxel.
DVSGI_CONST(uint, VOXEL_EXTENT_STEPS, 8);
DVSGI_CONST(uint, VOXEL_EXTENT_ALL, 0xffffffu);
// Within this many eighths of an eighth's border, a box's end counts as on
// it: a plane on a border then falls in the same eighth whichever way the
// grid's origin rounded its coordinates (a clipmap level's kept voxels keep
// the extents their voxelization under the level's old origin gave; the voxel
// light looks shadows up from the extents: lib/voxel_extents.glsl). f is in
// eighths; the bits clamp to [0, 8] anyway, and clamping first keeps int()
// in range.
DVSGI_CONST(float, VOXEL_EXTENT_SNAP, 4e-3);
DVSGI_FUNCTION float snapToExtentBorder(float f) {
    f = f < -1.0f ? -1.0f : (f > 9.0f ? 9.0f : f);
    float r = float(int(f + (f >= 0.0f ? 0.5f : -0.5f)));
    return f - r < VOXEL_EXTENT_SNAP && r - f < VOXEL_EXTENT_SNAP ? r : f;
}
// One axis's bits for a box from lo to hi along it, in voxels from the
// voxel's low face (clamped to the voxel: a box reaching past it covers it to
// that face).
DVSGI_FUNCTION uint voxelExtentAxisBits(float lo, float hi) {
    float fa = snapToExtentBorder(lo * float(VOXEL_EXTENT_STEPS)), fb = snapToExtentBorder(hi * float(VOXEL_EXTENT_STEPS));
    int a = fa <= 0.0f ? 0 : (fa >= 7.0f ? 7 : int(fa));
    int b = fb <= 1.0f ? 0 : (fb >= 8.0f ? 7 : (float(int(fb)) == fb ? int(fb) - 1 : int(fb)));
    if (b < a) b = a;
    return ((2u << uint(b)) - 1u) & ~((1u << uint(a)) - 1u);
}
// A box's bits on all three axes, lo and hi relative to the voxel's low corner.
DVSGI_FUNCTION uint voxelExtentBits(vec3 lo, vec3 hi) {
    uint bits = 0u;
    for (int k = 0; k < 3; ++k) bits |= voxelExtentAxisBits(lo[k], hi[k]) << (VOXEL_EXTENT_STEPS * uint(k));
    return bits;
}

// Thin walls. A voxel whose normal weights hold both signs of one axis (each
// at least TWO_SIDED_MIN_WEIGHT) holds both faces of a wall thinner than a
// voxel, or two surfaces facing each other across it: one radiance cannot
// serve both sides. Such a voxel is lit and bounced per side as well, and
// rays along that axis see the side they meet (shaders/lib/voxel_sides.glsl).
// Its side code (SIDE_*) is kept in the alpha of its direct light, as
// 1 + code, so that one-sided voxels keep alpha 1.
DVSGI_CONST(float, TWO_SIDED_MIN_WEIGHT, 0.1);
DVSGI_CONST(uint, SIDE_ONE, 0);      // one-sided: the same radiance every way
// 1-3: two-sided along axis code - 1
DVSGI_CONST(uint, SIDE_SEVERAL, 4);  // two-sided along several axes: an edge or corner where thin walls meet
// The radiance volume's opacity of a voxel with side code c other than
// SIDE_ONE: 1 - c * 2^-11, fp16 values just below 1, so that the filter looks
// up the side light of these voxels only and the per-pixel cones tell a thin
// wall's axis (twoSidedOpacity below). Cones sampling the
// radiance volume let through under 2e-3 of such a voxel instead of 1e-4
// (the tracer caps opacity at 0.9999), and the near samples read the
// directional volumes there instead.
DVSGI_CONST(float, TWO_SIDED_OPACITY_STEP, 0.00048828125);
// The axis (0-2) along which a voxel with side code `code` is two-sided; -1
// for SIDE_ONE and SIDE_SEVERAL.
DVSGI_FUNCTION int twoSidedAxis(uint code) { return code >= 1u && code <= 3u ? int(code) - 1 : -1; }
// The radiance volume's opacity of a voxel with side code `code`.
DVSGI_FUNCTION float twoSidedOpacity(uint code) { return 1.0f - float(code) * TWO_SIDED_OPACITY_STEP; }
// Whether a radiance texel's opacity marks a two-sided voxel (occupied
// one-sided voxels have 1, empty ones 0): a voxel whose side code is not SIDE_ONE.
DVSGI_FUNCTION bool marksTwoSided(float opacity) { return opacity > 0.0f && opacity < 1.0f; }
// The side code a radiance texel's opacity holds (SIDE_ONE unless marked).
DVSGI_FUNCTION uint sideCodeOfOpacity(float opacity) {
    return marksTwoSided(opacity) ? uint((1.0f - opacity) / TWO_SIDED_OPACITY_STEP + 0.5f) : SIDE_ONE;
}

// A one-sided voxel shows its light to the rays that meet its front (with
// --voxel-backs-dark, the default; the filter's directional volumes and the
// rays of the bounce and the gather): fully while the travel direction t has
// dot(n, t) <= VOXEL_BACK_FADE_START (seen face on, or edge on), none from
// VOXEL_BACK_FADE_END (seen from behind); lib/voxel_sides.glsl, seenFromFront.
DVSGI_CONST(float, VOXEL_BACK_FADE_START, 0.1);
DVSGI_CONST(float, VOXEL_BACK_FADE_END, 0.35);
// The share of its light a one-sided voxel shows a ray, from along = dot(n, t).
DVSGI_FUNCTION float voxelBackFade(float along) {
    float f = (VOXEL_BACK_FADE_END - along) / (VOXEL_BACK_FADE_END - VOXEL_BACK_FADE_START);
    return f < 0.0f ? 0.0f : (f > 1.0f ? 1.0f : f);
}

// Slots per row of the per-slot images (attributes, voxel direct light);
// capacities are whole rows.
DVSGI_CONST(uint, VOXEL_SLOT_ROW, 4096);
// Index volume values: slot + 1 in the low 31 bits, the static bit on top.
DVSGI_CONST(uint, VOXEL_INDEX_STATIC, 0x80000000u);
DVSGI_CONST(uint, VOXEL_INDEX_SLOT_MASK, 0x7FFFFFFFu);
// Transient while the voxelizer that claimed the voxel takes its slot.
DVSGI_CONST(uint, VOXEL_INDEX_LOCKED, 0xFFFFFFFFu);
// Claimed when every slot was taken: no slot, the fragment is dropped and
// counted (VoxelListHeader.counts.w), and the host grows the storage and
// voxelizes again. Not all ones, so that with the static bit it still differs
// from VOXEL_INDEX_LOCKED.
DVSGI_CONST(uint, VOXEL_INDEX_FULL, 0x7FFFFFFEu);
// Reads of a locked index before a waiting invocation gives up (claimVoxel).
DVSGI_CONST(uint, VOXEL_CLAIM_SPINS, 1u << 20);

// slot + 1 of an index value, or 0 for an empty voxel (and for the locked and
// overflow values, which own no slot).
DVSGI_FUNCTION uint indexSlot(uint value) {
    uint slot = value & VOXEL_INDEX_SLOT_MASK;
    return slot >= VOXEL_INDEX_FULL ? 0u : slot;
}

// The six directional volumes (order -X +X -Y +Y -Z +Z, the direction light
// travels) lie side by side along x in one 3D image with mips, the atlas:
// a cone picks the three it faces by arithmetic, with no per-lane descriptor
// index (lavapipe has no non-uniform sampler indexing) and without fetching
// the three facing away. Volume d's cell p, at a level of `size` cells per edge:
DVSGI_CONST(uint, DIRECTIONAL_VOLUMES, 6);
DVSGI_FUNCTION ivec3 directionalTexel(uint d, ivec3 p, int size) { return ivec3(p.x + int(d) * size, p.y, p.z); }

struct VoxelGrid {
    vec4 originSize;  // xyz world position of the grid's minimum corner, w voxel edge (m)
    uvec4 dims;       // x N (voxels per edge), y channels, z mip count of the directional volumes, w slot capacity
    // Toroidal addressing of the index and the list (clipmap levels,
    // vxgi/clipmap.h): xyz the storage voxel of the grid's voxel 0, which is
    // the window's minimum corner in whole voxels of the level modulo N; 0 for
    // a fitted grid. The dense volumes (radiance, directional) are not
    // toroidal: they are rebuilt every frame in grid coordinates.
    ivec4 wrap;
    // keep.w != 0: static voxelization skips the grid voxels in
    // [keep.xyz, keep.xyz + N), those a scroll kept (only the slabs it exposed
    // are voxelized).
    ivec4 keep;
};
DVSGI_CHECK_SIZE(VoxelGrid, 64);

// Clipmap levels as one cone tracer sees them (lib/cone_trace.glsl with
// DVSGI_CLIPMAP): level l's grid, each twice the voxel of the one before.
DVSGI_CONST(uint, MAX_CLIP_LEVELS, 8);
struct ConeLevels {
    VoxelGrid level[MAX_CLIP_LEVELS];
    uvec4 count;  // x levels in use
};
DVSGI_CHECK_SIZE(ConeLevels, 528);

// Occlusion of a light at voxels (GpuLight.shadow.z, or a global override).
DVSGI_CONST(uint, OCCLUSION_SHADOW_MAP, 0);
DVSGI_CONST(uint, OCCLUSION_RAYCAST_HARD, 1);
DVSGI_CONST(uint, OCCLUSION_RAYCAST_SOFT, 2);
DVSGI_CONST(uint, OCCLUSION_NONE, 3);
DVSGI_CONST(uint, OCCLUSION_PER_LIGHT, 4);  // no override

// Cone tracing through the filtered volumes (shared by the voxel bounce and
// the per-pixel gather).
struct ConeParams {
    vec4 trace;    // x step factor beta, y minimum step (voxels), z maximum distance (m), w first sample (voxels)
    vec4 surface;  // x clearance K (0 = off), y surface thickness (voxels): see traceConeAO,
                   // z origin offset along the normal (voxels), w aperture set (CONE_SET_*)
};
DVSGI_CHECK_SIZE(ConeParams, 32);

// Default cone clearance K and the thickness of a voxelized surface.
DVSGI_CONST(float, CONE_CLEARANCE_DEFAULT, 3.0);
DVSGI_CONST(float, CONE_SURFACE_VOXELS, 1.0);

// Diffuse aperture sets (ConeParams.surface.w).
DVSGI_CONST(uint, CONE_SET_6, 6);    // the paper's six 60-degree cones
DVSGI_CONST(uint, CONE_SET_16, 16);  // sixteen cones over the hemisphere

// Bindings of lib/cone_trace.glsl, the same in every pass that traces cones.
DVSGI_CONST(uint, BIND_CONE_GRID, 0);
DVSGI_CONST(uint, BIND_CONE_RADIANCE, 1);     // sampled, trilinear
DVSGI_CONST(uint, BIND_CONE_DIRECTIONAL, 2);  // sampled, trilinear + mips: the six volumes' atlas
// With DVSGI_CLIPMAP: BIND_CONE_GRID holds ConeLevels, and the sampled
// volumes are the clipmap's atlases (levels stacked along z).

DVSGI_END

#ifndef __cplusplus
// The texel of channel `channel` of slot `slot` in a per-slot image.
ivec3 slotTexel(uint slot, uint channel) { return ivec3(slot % VOXEL_SLOT_ROW, slot / VOXEL_SLOT_ROW, channel); }
// The index as the GLSL buffer block `voxelIndex` (N^3 uints, x fastest) at
// binding B of set 0, access qualifier Q. A buffer rather than an R32UI
// image: nothing filters it, and the host reads and writes it as plain words.
#define VOXEL_INDEX_BLOCK(B, Q) \
    layout(set = 0, binding = B, std430) Q buffer VoxelIndex { uint voxelIndex[]; }
// The extents (VOXEL_EXTENT_*), one uint per slot.
#define VOXEL_EXTENTS_BLOCK(B, Q) \
    layout(set = 0, binding = B, std430) Q buffer VoxelExtents { uint voxelExtents[]; }
#endif

#endif
