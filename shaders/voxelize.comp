#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
#include "shared/geometry_pass.h"
#include "shared/scene_data.h"
#include "shared/voxel_data.h"
#include "shared/voxelize_compute_pass.h"
#include "shared/voxelize_pass.h"
#include "shared/voxel_list_pass.h"

// Compute voxelization: every voxel whose closed box a triangle touches, by an
// exact separating-axis test, gets one sample of the triangle's material.
//
// Triangle phase: one invocation per triangle (a workgroup never mixes draws,
// so texture indices stay uniform). The triangle is projected along its
// dominant axis, as voxelize.geom does; each voxel column of its clipped
// bounding box there holds at most a few candidate layers, those the plane
// crosses over the column (|slope| <= 1 per axis), and the exact test decides
// each. A triangle with more than pc.tiling.x columns queues tiles instead.
// Tile phase (indirect): one workgroup per tile, one invocation per
// pc.tiling.y columns of a row (VOXC_TILE rows of VOXC_TILE invocations).
//
// The sample: the material at the point of the triangle nearest the voxel
// centre. It lies inside the triangle, so its UV never leaves the triangle's
// texture region (the dilated raster path extrapolates); it is the part of
// the triangle the voxel holds, or the nearest part when only an edge or
// corner enters the box.
layout(local_size_x = VOXC_GROUP) in;

layout(set = 0, binding = BIND_VOXC_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_VOXC_DRAWS, std430) readonly buffer Draws { GpuDraw draws[]; };
layout(set = 0, binding = BIND_VOXC_MATERIALS, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 0, binding = BIND_VOXC_ACCUM, r32f) uniform coherent image3D accum;
VOXEL_INDEX_BLOCK(BIND_VOXC_INDEX, coherent);
VOXEL_EXTENTS_BLOCK(BIND_VOXC_EXTENTS, );
layout(set = 0, binding = BIND_VOXC_VERTICES, std430) readonly buffer Vertices { float vertexData[]; };
layout(set = 0, binding = BIND_VOXC_INDICES, std430) readonly buffer Indices { uint indexData[]; };
layout(set = 0, binding = BIND_VOXC_GROUPS, std430) readonly buffer Groups { VoxcGroup groups[]; };
layout(set = 0, binding = BIND_VOXC_TILES, std430) buffer Tiles { VoxcTile tiles[]; };
layout(set = 0, binding = BIND_VOXC_INDIRECT, std430) buffer Indirect { uint indirect[4]; };
VOXEL_LIST_BLOCK(BIND_VOXC_LIST, );
layout(set = SET_TEXTURES, binding = BIND_TEXTURES) uniform texture2D textures[MAX_TEXTURES];
layout(set = SET_TEXTURES, binding = BIND_TEXTURE_SAMPLER) uniform sampler textureSampler;
layout(push_constant) uniform Push { VoxelizeComputePush pc; };

#define MATERIAL_EXPLICIT_LOD
#include "lib/material.glsl"
#include "lib/triangle_box.glsl"
#include "lib/voxel_index.glsl"
#include "lib/voxel_accumulate.glsl"

struct Triangle {
    vec3 p[3];       // voxel units, bit-identical to the CPU reference's
    dvec3 v[3];      // the same, for the exact test
    dvec3 e[3];      // v1 - v0, v2 - v1, v0 - v2
    dvec3 n;         // crossExact(e0, e1)
    vec3 normal[3];  // world vertex normals
    vec2 uv[3];
    uint axis;       // dominant axis of the face normal (voxelize.geom's choice)
    ivec3 lo, hi;    // closed voxel range of the bounding box in the grid, projected order (z = axis)
    vec2 slope;      // plane: dz/du, dz/dv in projected order
    bool planar;     // false for a degenerate triangle: every layer of the box is a candidate
    uint material;
};
// The invocation's triangle: one global, not a by-value argument (passed by
// value, Sponza's 256^3 voxelization took 1.25x as long on lavapipe:
// docs/benchmarks.md).
Triangle t;

vec3 project(vec3 p, uint axis) { return axis == 0u ? p.yzx : (axis == 1u ? p.zxy : p.xyz); }
ivec3 project(ivec3 p, uint axis) { return axis == 0u ? p.yzx : (axis == 1u ? p.zxy : p.xyz); }
ivec3 unproject(ivec3 p, uint axis) { return axis == 0u ? p.zxy : (axis == 1u ? p.yzx : p.xyz); }

vec3 loadVec3(uint at) { return vec3(vertexData[at], vertexData[at + 1u], vertexData[at + 2u]); }

// False when the triangle's bounding box misses the grid.
bool loadTriangle(uint draw, uint firstIndex, int vertexOffset) {
    GpuDraw d = draws[draw];
    mat3 normalMatrix = mat3(d.normalMatrix);
    for (uint k = 0u; k < 3u; ++k) {
        uint at = uint(int(indexData[firstIndex + k]) + vertexOffset) * VOXC_VERTEX_FLOATS;
        vec3 pos = loadVec3(at);
        // glm's mat4 * vec4 order, then (world - origin) / size: the tests'
        // reference sees the same float coordinates.
        precise vec3 a0 = d.model[0].xyz * pos.x + d.model[1].xyz * pos.y;
        precise vec3 a1 = d.model[2].xyz * pos.z + d.model[3].xyz;
        precise vec3 world = a0 + a1;
        precise vec3 p = (world - grid.originSize.xyz) / grid.originSize.w;
        t.p[k] = p;
        t.v[k] = dvec3(p);
        t.normal[k] = normalMatrix * loadVec3(at + 3u);
        t.uv[k] = vec2(vertexData[at + 6u], vertexData[at + 7u]);
    }
    t.material = d.info.x;
    for (int k = 0; k < 3; ++k) t.e[k] = t.v[(k + 1) % 3] - t.v[k];
    t.n = crossExact(t.e[0], t.e[1]);

    vec3 faceNormal = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
    vec3 an = abs(faceNormal);
    t.axis = (an.x >= an.y && an.x >= an.z) ? 0u : (an.y >= an.z ? 1u : 2u);
    // Closed, grown boxes: a coordinate on a voxel face touches the voxels on both sides.
    vec3 lo = min(t.p[0], min(t.p[1], t.p[2])), hi = max(t.p[0], max(t.p[1], t.p[2]));
    int N = int(grid.dims.x);
    ivec3 a = max(ivec3(ceil(lo - VOXC_BOX_GROWTH)) - 1, ivec3(0));
    ivec3 b = min(ivec3(floor(hi + VOXC_BOX_GROWTH)), ivec3(N - 1));
    if (any(greaterThan(a, b))) return false;
    if (pc.ids.z != VOXELIZE_DYNAMIC) {
        if (rangeKeptByScroll(a, b)) return false;
        // Only the exposed slab's voxels are tested (both phases load the
        // triangle here, so tiles and columns agree).
        clipRangeToExposed(a, b);
    }
    t.lo = project(a, t.axis);
    t.hi = project(b, t.axis);
    dvec3 nq = t.axis == 0u ? t.n.yzx : (t.axis == 1u ? t.n.zxy : t.n.xyz);
    t.planar = nq.z != 0.0LF;
    t.slope = t.planar ? vec2(-nq.xy / nq.z) : vec2(0.0);
    // Texture level: texture area per unit of surface area (voxel units).
    vec2 du = t.uv[1] - t.uv[0], dv = t.uv[2] - t.uv[0];
    float area = length(faceNormal);
    materialUvDensity = area > 0.0 ? abs(du.x * dv.y - du.y * dv.x) / area : 0.0;
    return true;
}

// Barycentric coordinates of the point of triangle abc nearest p (Ericson,
// Real-Time Collision Detection 5.1.5); the centroid for a degenerate one.
vec3 nearestBarycentric(vec3 p, vec3 a, vec3 b, vec3 c) {
    vec3 ab = b - a, ac = c - a, ap = p - a;
    float d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return vec3(1, 0, 0);
    vec3 bp = p - b;
    float d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return vec3(0, 1, 0);
    vec3 cp = p - c;
    float d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return vec3(0, 0, 1);
    float vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    vec3 bary;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        float s = d1 / (d1 - d3);
        bary = vec3(1.0 - s, s, 0.0);
    } else if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        float s = d2 / (d2 - d6);
        bary = vec3(1.0 - s, 0.0, s);
    } else if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
        float s = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        bary = vec3(0.0, 1.0 - s, s);
    } else {
        float inv = 1.0 / (va + vb + vc);
        bary = vec3(1.0 - (vb + vc) * inv, vb * inv, vc * inv);
    }
    return any(isnan(bary)) || any(isinf(bary)) ? vec3(1.0 / 3.0) : bary;
}

// One sample of the triangle's material into `voxel` (projected coordinates
// `q`: the alpha-blend threshold uses the pixel centre voxelize.frag would).
void addSample(ivec3 voxel, ivec3 q) {
    vec3 bary = nearestBarycentric(vec3(voxel) + 0.5, t.p[0], t.p[1], t.p[2]);
    vec2 uv = bary.x * t.uv[0] + bary.y * t.uv[1] + bary.z * t.uv[2];
    GpuMaterial m = materials[t.material];
    // Base colour and emissive texture through one sampleTexture call (see
    // material.glsl: each call site costs lavapipe a 96-way switch).
    vec4 texel[2] = vec4[2](vec4(1.0), vec4(1.0));
    for (uint i = 0u; i < pc.dispatch.z; ++i) {
        int index = i == 0u ? m.textures.x : m.textures.y;
        if (index != NO_TEXTURE) texel[i] = sampleTexture(index, i == 0u ? m.textureSizes.xy : m.textureSizes.zw, uv);
    }
    vec4 base = m.baseColor * texel[0];  // sRGB views decode
    if (!materialCovers(m, base.a, vec2(q.xy) + 0.5)) return;
    vec3 emission = m.emission.rgb * texel[1].rgb;
    vec3 n = normalize(bary.x * t.normal[0] + bary.y * t.normal[1] + bary.z * t.normal[2]);
    uint slot1 = accumulateFragment(voxel, pc.ids.z, base.rgb, emission, n);
    if (slot1 == 0u) return;
    // Where in the voxel the triangle can be: its bounding box, per axis.
    vec3 lo = min(t.p[0], min(t.p[1], t.p[2])), hi = max(t.p[0], max(t.p[1], t.p[2]));
    atomicOr(voxelExtents[slot1 - 1u], voxelExtentBits(lo - vec3(voxel), hi - vec3(voxel)));
}

// The candidate layers of a column: those the plane crosses over the closed
// column (from vertex 0; the margin covers float rounding, the exact test
// decides), or every layer of the box for a degenerate triangle.
void columnLayers(ivec2 column, out int first, out int last) {
    first = t.lo.z;
    last = t.hi.z;
    if (!t.planar) return;
    vec3 q0 = project(t.p[0], t.axis);
    vec2 d = vec2(column) - q0.xy;
    float z = q0.z + t.slope.x * d.x + t.slope.y * d.y;
    float zmin = z + min(t.slope.x, 0.0) + min(t.slope.y, 0.0);
    float zmax = z + max(t.slope.x, 0.0) + max(t.slope.y, 0.0);
    float margin = 1e-3 + 1e-5 * (abs(q0.z) + abs(d.x) + abs(d.y));
    first = max(first, int(floor(zmin - margin)));
    last = min(last, int(floor(zmax + margin)));
}

// Every candidate voxel of the columns from..to (inclusive, projected order),
// row by row, walked by one invocation. The walk stores its hits and samples
// them pc.tiling.z at a time in a loop of their own: llvmpipe runs an if's
// body for every lane batch under a mask, so a sample taken inside the walk
// cost every candidate of every lane its texture fetches and atomics
// (docs/benchmarks.md).
ivec3 pending[VOXC_PENDING];

void walkColumns(ivec2 from, ivec2 to) {
    ivec2 column = from;
    int layer, last;
    columnLayers(column, layer, last);
    bool done = false;
    while (!done) {
        uint count = 0u;
        while (!done && count < pc.tiling.z) {
            if (layer <= last) {
                ivec3 voxel = unproject(ivec3(column, layer), t.axis);
                if (triangleTouchesVoxel(t.v[0], t.v[1], t.v[2], t.e[0], t.e[1], t.e[2], t.n, voxel))
                    pending[count++] = voxel;
            }
            if (++layer > last) {
                if (++column.x > to.x) {
                    column.x = from.x;
                    done = ++column.y > to.y;
                }
                columnLayers(column, layer, last);
            }
        }
        for (uint i = 0u; i < count; ++i) addSample(pending[i], project(pending[i], t.axis));
    }
}

// Claims `count` consecutive tile slots; false when they do not fit. The
// dispatch grows to cover them (both counts only ever grow, so atomicMax
// orders concurrent claims).
bool reserveTiles(uint count, out uint slot) {
    uint seen = 0u;
    for (;;) {
        if (seen + count > VOXC_MAX_TILES) return false;
        uint before = atomicCompSwap(indirect[3], seen, seen + count);
        if (before == seen) break;
        seen = before;
    }
    slot = seen;
    uint end = seen + count;
    atomicMax(indirect[0], min(end, VOXC_TILE_ROW));
    atomicMax(indirect[1], (end + VOXC_TILE_ROW - 1u) / VOXC_TILE_ROW);
    return true;
}

// A tile: VOXC_TILE rows of VOXC_TILE invocations, each walking pc.tiling.y
// consecutive columns of its row (columns x rows).
ivec2 tileSize() { return ivec2(int(VOXC_TILE * pc.tiling.y), int(VOXC_TILE)); }

void trianglePhase() {
    uint groupIndex = gl_WorkGroupID.y * pc.dispatch.x + gl_WorkGroupID.x;
    if (groupIndex >= pc.ids.y) return;
    VoxcGroup g = groups[pc.ids.x + groupIndex];
    uint local = gl_LocalInvocationID.x;
    if (local >= g.draw.w) return;
    uint firstIndex = g.draw.y + 3u * local;
    if (!loadTriangle(g.draw.x, firstIndex, int(g.draw.z))) return;
    ivec2 span = t.hi.xy - t.lo.xy + 1;
    if (uint(span.x * span.y) > pc.tiling.x) {
        uvec2 tileSpan = uvec2((span + tileSize() - 1) / tileSize());
        uint count = tileSpan.x * tileSpan.y, slot;
        if (reserveTiles(count, slot)) {
            for (uint i = 0u; i < count; ++i) tiles[slot + i].item = uvec4(g.draw.x, firstIndex, g.draw.z, i);
            return;
        }
    }
    walkColumns(t.lo.xy, t.hi.xy);
}

void tilePhase() {
    uint tileIndex = gl_WorkGroupID.y * VOXC_TILE_ROW + gl_WorkGroupID.x;
    if (tileIndex >= indirect[3]) return;  // the last row's tail
    uvec4 item = tiles[tileIndex].item;
    if (!loadTriangle(item.x, item.y, int(item.z))) return;
    int laneColumns = int(pc.tiling.y);
    int tilesPerRow = (t.hi.x - t.lo.x + tileSize().x) / tileSize().x;
    int tile = int(item.w), local = int(gl_LocalInvocationID.x);
    ivec2 from = t.lo.xy + ivec2(tile % tilesPerRow, tile / tilesPerRow) * tileSize() +
                 ivec2(local % int(VOXC_TILE) * laneColumns, local / int(VOXC_TILE));
    if (any(greaterThan(from, t.hi.xy))) return;
    walkColumns(from, ivec2(min(from.x + laneColumns - 1, t.hi.x), from.y));
}

void main() {
    materialTaps = pc.dispatch.y;
    if (pc.ids.w == VOXC_PHASE_TRIANGLES) trianglePhase();
    else tilePhase();
}
