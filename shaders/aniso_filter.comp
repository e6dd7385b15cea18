#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/aniso_filter_pass.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"

// Anisotropic filtering (paper section VII). Each target voxel covers 2x2x2
// source voxels. For each of the six travel directions, the four child columns
// along that axis are composited front to back (front + back * (1 - front.a),
// "front" = the child a ray travelling that way enters first) and averaged.
// The base level reads the radiance volume for all six directions; each upper
// level reads the same direction's previous level.
//
// The base level runs over the occupied-voxel list, one invocation per entry,
// and the cell's first occupied voxel (x fastest) composites it; the caller
// clears the level first. Most of a grid is empty, and a dense pass read
// eight voxels of every empty cell and wrote its six zeros (Sponza 256^3: 2.1M
// cells, about 200k of them occupied).
//
// With DVSGI_TWO_SIDED, the base level's second pass: one invocation per entry of
// the occupied-voxel list, and for each two-sided voxel (lib/voxel_sides.glsl)
// its cell again, now with the voxel showing rays along its axis the side they
// meet and rays across it an opaque black edge (a thin wall seen edge-on shows
// neither face; showing eq. 5's radiance let a sunlit roof light the room
// below it, docs/quality.md), and a voxel two-sided along several axes black
// every way. The cell's first two-sided voxel writes it. A pass of its own, so
// that the first, over every occupied voxel, need not look up side codes
// (llvmpipe runs both sides of a branch).
#if defined(DVSGI_TWO_SIDED) || defined(DVSGI_BASE_LEVEL)
layout(local_size_x = VOXEL_LIST_GROUP) in;
#else
layout(local_size_x = ANISO_GROUP, local_size_y = ANISO_GROUP, local_size_z = ANISO_GROUP) in;
#endif

layout(set = 0, binding = BIND_ANISO_SOURCE, rgba16f) uniform readonly image3D source;
layout(set = 0, binding = BIND_ANISO_SOURCE_DIRS, rgba16f) uniform readonly image3D sourceDirs;
layout(set = 0, binding = BIND_ANISO_TARGET_DIRS, rgba16f) uniform writeonly image3D targetDirs;
layout(push_constant) uniform Push { AnisoPush pc; };

#if defined(DVSGI_TWO_SIDED) || defined(DVSGI_BASE_LEVEL)
layout(set = 0, binding = BIND_ANISO_GRID) uniform Grid { VoxelGrid grid; };
VOXEL_LIST_BLOCK(BIND_ANISO_LIST, readonly);
VOXEL_INDEX_BLOCK(BIND_ANISO_INDEX, readonly);
layout(set = 0, binding = BIND_ANISO_ACCUM, r32f) uniform readonly image3D accum;
#include "lib/voxel_window.glsl"
#include "lib/voxel_list_dispatch.glsl"
#include "lib/voxel_index.glsl"
#include "lib/voxel_attributes.glsl"

// A one-sided voxel seen from behind shows no light but still blocks: its
// light leaves its front, and behind a surface lies the solid it bounds or
// the surface's other face, which is a voxel of its own or makes this one
// two-sided. Shown the same every way, a lit face reached cones that could
// only have met it from behind: in a cell holding a block's lit top but not
// its bottom, rays travelling up saw the top, and the per-pixel gather
// over-counted beside such blocks (docs/quality.md, "A voxel seen from
// behind"). `n`: the voxel's mean normal (0 where its faces cancel: shown
// every way).
float seenFront(vec3 n, uint dir) {
    float along = (dir % 2u == 0u ? -1.0 : 1.0) * n[dir / 2u];  // dot(n, travel direction)
    return voxelBackFade(along);
}

// The mean normal of the voxel in `slot` (slot + 1; 0: empty, normal 0), and
// 0 for every voxel when the voxels show their light every way (pc.sizes.y = 0).
vec3 normalOfSlot(uint slot) {
    return pc.sizes.y == 0u || slot == 0u ? vec3(0.0) : voxelNormalDirection(slot - 1u);
}
#endif

#ifdef DVSGI_TWO_SIDED
layout(set = 0, binding = BIND_ANISO_DIRECT, rgba16f) uniform readonly image3D direct;
layout(set = 0, binding = BIND_ANISO_SIDES, rgba32ui) uniform readonly uimage3D sides;

#include "lib/voxel_sides.glsl"

// The cell's eight voxels as the six directions see them: the radiance, and
// for a two-sided voxel its axis and its two sides (+axis, -axis).
vec4 children[8];
vec3 childNormal[8];
int childAxis[8];  // -1: one-sided
vec3 childSide[8][2];

// The side code of the voxel in `slot` (slot + 1; 0: empty).
uint sideCodeOfSlot(uint slot) {
    return slot == 0u ? SIDE_ONE : sideCodeOf(imageLoad(direct, slotTexel(slot - 1u, 0u)));
}

void loadChildren(ivec3 base) {
    for (int i = 0; i < 8; ++i) {
        ivec3 p = base + ivec3(i & 1, (i >> 1) & 1, i >> 2);
        children[i] = imageLoad(source, p);
        childAxis[i] = -1;
        // One index lookup for the normal and the side code.
        uint slot = children[i].a > 0.0 ? voxelSlotAt(p) : 0u;
        childNormal[i] = normalOfSlot(slot);
        uint code = marksTwoSided(children[i].a) ? sideCodeOfSlot(slot) : SIDE_ONE;
        if (code == SIDE_ONE) continue;
        children[i] = vec4(0.0, 0.0, 0.0, 1.0);
        if (code == SIDE_SEVERAL) continue;  // where thin walls meet no side is the one a ray meets
        uvec4 t = imageLoad(sides, slotTexel(slot - 1u, 0u));
        childAxis[i] = int(code) - 1;
        childSide[i][0] = unpackRgb9e5(t.x) + unpackRgb9e5(t.z);
        childSide[i][1] = unpackRgb9e5(t.y) + unpackRgb9e5(t.w);
    }
}

vec4 child(uint dir, ivec3 p) {
    int i = (p.x & 1) + 2 * (p.y & 1) + 4 * (p.z & 1);
    // Travelling toward -axis (even dir) a ray meets the +axis side.
    if (childAxis[i] == int(dir / 2u)) return vec4(childSide[i][dir % 2u == 0u ? 0 : 1], 1.0);
    return vec4(children[i].rgb * seenFront(childNormal[i], dir), children[i].a);
}
#elif defined(DVSGI_BASE_LEVEL)
// The cell's eight voxels and their normals, loaded once for the six directions.
vec4 children[8];
vec3 childNormal[8];

void loadChildren(ivec3 base) {
    for (int i = 0; i < 8; ++i) {
        ivec3 p = base + ivec3(i & 1, (i >> 1) & 1, i >> 2);
        children[i] = imageLoad(source, p);
        childNormal[i] = normalOfSlot(children[i].a > 0.0 && pc.sizes.y != 0u ? voxelSlotAt(p) : 0u);
    }
}

vec4 child(uint dir, ivec3 p) {
    int i = (p.x & 1) + 2 * (p.y & 1) + 4 * (p.z & 1);
    return vec4(children[i].rgb * seenFront(childNormal[i], dir), children[i].a);
}
#else
// The levels above the base are a variant of their own rather than a branch
// on the level: llvmpipe took both loads of such a branch for every child.
vec4 child(uint dir, ivec3 p) { return imageLoad(sourceDirs, directionalTexel(dir, p, 2 * int(pc.sizes.x))); }
#endif

void composite(ivec3 v, int size) {
    ivec3 base = v * 2;
    for (uint dir = 0u; dir < DIRECTIONAL_VOLUMES; ++dir) {
        int axis = int(dir / 2u);
        // Travelling toward -axis (even dir) the ray enters the +axis child first.
        int frontOffset = (dir % 2u == 0u) ? 1 : 0;
        vec4 sum = vec4(0.0);
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) {
                ivec3 front = ivec3(0), back = ivec3(0);
                // (a, b) index the two axes other than `axis`.
                int u = (axis + 1) % 3, w = (axis + 2) % 3;
                front[u] = a; front[w] = b; front[axis] = frontOffset;
                back[u] = a; back[w] = b; back[axis] = 1 - frontOffset;
                vec4 f = child(dir, base + front), k = child(dir, base + back);
                sum += f + k * (1.0 - f.a);
            }
        imageStore(targetDirs, directionalTexel(dir, v, size), sum * 0.25);
    }
}

#if defined(DVSGI_TWO_SIDED) || defined(DVSGI_BASE_LEVEL)
// Whether voxel p, of a cell that an earlier voxel may own, claims it: any
// occupied voxel for the base level, a two-sided one for the two-sided pass.
bool claims(ivec3 p) {
    float a = imageLoad(source, p).a;
#ifdef DVSGI_TWO_SIDED
    return marksTwoSided(a);
#else
    return a > 0.0;
#endif
}

void main() {
    uint entry = listInvocation();
    if (entry >= list.header.counts.x || list.entries[entry] == VOXEL_LIST_FREE) return;
    ivec3 voxel = listVoxel(list.entries[entry]);
#ifdef DVSGI_TWO_SIDED
    if (sideCodeOf(imageLoad(direct, slotTexel(entry, 0u))) == SIDE_ONE) return;
#endif
    ivec3 v = voxel / 2;
    // The cell's first claiming voxel (x fastest) owns it.
    int self = (voxel.x & 1) + 2 * (voxel.y & 1) + 4 * (voxel.z & 1);
    for (int i = 0; i < self; ++i) {
        if (claims(v * 2 + ivec3(i & 1, (i >> 1) & 1, i >> 2))) return;
    }
    loadChildren(v * 2);
    composite(v, int(pc.sizes.x));
}
#else
void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, ivec3(pc.sizes.x)))) return;
    ivec3 base = v * 2;
    int size = int(pc.sizes.x);
    // Most of a grid is empty. Where the eight children of one direction are
    // all zero, so are the other five's (each is a composite of the same
    // voxels) and every result: eight loads decide it instead of the 48 below.
    // Empty regions are large, so whole SIMD groups take this branch together.
    bool empty = true;
    for (int i = 0; i < 8; ++i) empty = empty && all(equal(child(0u, base + ivec3(i & 1, (i >> 1) & 1, i >> 2)), vec4(0.0)));
    if (empty) {
        for (uint dir = 0u; dir < DIRECTIONAL_VOLUMES; ++dir) imageStore(targetDirs, directionalTexel(dir, v, size), vec4(0.0));
        return;
    }
    composite(v, size);
}
#endif
