#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
#include "shared/scene_data.h"
#include "shared/geometry_pass.h"
#include "shared/voxel_data.h"
#include "shared/voxelize_pass.h"
#include "shared/voxel_list_pass.h"

layout(set = 0, binding = BIND_VOX_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_VOX_MATERIALS, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 0, binding = BIND_VOX_ACCUM, r32f) uniform coherent image3D accum;
VOXEL_INDEX_BLOCK(BIND_VOX_INDEX, coherent);
VOXEL_LIST_BLOCK(BIND_VOX_LIST, );
VOXEL_EXTENTS_BLOCK(BIND_VOX_EXTENTS, );
layout(set = SET_TEXTURES, binding = BIND_TEXTURES) uniform texture2D textures[MAX_TEXTURES];
layout(set = SET_TEXTURES, binding = BIND_TEXTURE_SAMPLER) uniform sampler textureSampler;
layout(push_constant) uniform Push { VoxelizePush pc; };

#define MATERIAL_EXPLICIT_LOD
#include "lib/material.glsl"
#include "lib/voxel_index.glsl"
#include "lib/voxel_accumulate.glsl"

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec2 inUV;
layout(location = 2) flat in uint inMaterial;
layout(location = 3) flat in uint inAxis;
layout(location = 4) flat in vec4 inAabb;
layout(location = 5) flat in vec3 inTri[3];

ivec3 unswizzle(ivec3 p, uint axis) {
    return axis == 0u ? p.zxy : (axis == 1u ? p.yzx : p.xyz);
}
vec3 unswizzle(vec3 p, uint axis) {
    return axis == 0u ? p.zxy : (axis == 1u ? p.yzx : p.xyz);
}

// Float slack (pixels) for the clip: a triangle that only touches the
// column's border must not be clipped away by rounding.
const float CLIP_SLACK = 1e-3;

// Depth range (voxel units) of the part of the triangle inside the pixel
// column [column, column + 1]^2, by Sutherland-Hodgman clipping; false when
// nothing is left (a pixel the dilation reached without the triangle touching
// the column). The part is convex, so the voxel layers it reaches are exactly
// those its depth range meets.
bool columnDepthRange(vec2 column, out vec2 range) {
    vec3 poly[7], clipped[7];
    int count = 3;
    for (int i = 0; i < 3; ++i) poly[i] = inTri[i];
    for (int side = 0; side < 4; ++side) {
        int a = side & 1;                  // clipped coordinate: x or y
        float s = side < 2 ? -1.0 : 1.0;   // keep s * p[a] <= bound
        float bound = side < 2 ? -(column[a] - CLIP_SLACK) : column[a] + 1.0 + CLIP_SLACK;
        int m = 0;
        for (int i = 0; i < count; ++i) {
            vec3 p = poly[i], q = poly[(i + 1) % count];
            float dp = s * p[a] - bound, dq = s * q[a] - bound;
            if (dp <= 0.0) clipped[m++] = p;
            if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) clipped[m++] = mix(p, q, dp / (dp - dq));
        }
        count = m;
        if (count == 0) return false;
        for (int i = 0; i < count; ++i) poly[i] = clipped[i];
    }
    range = vec2(poly[0].z);
    for (int i = 1; i < count; ++i) range = vec2(min(range.x, poly[i].z), max(range.y, poly[i].z));
    return true;
}

void main() {
    // Textures are fetched by hand as the compute voxelizer does (lib/material.glsl): on lavapipe,
    // texture() on the dynamically indexed array sampled a material's texture wrong, white over a
    // half-black one. The level comes from the texture area per voxel area of the projected
    // triangle (the rasterizer's pixels are voxel columns), taken before any fragment of the quad
    // is discarded.
    vec2 du = dFdx(inUV), dv = dFdy(inUV);
    materialUvDensity = abs(du.x * dv.y - du.y * dv.x);
    vec2 pc2 = gl_FragCoord.xy;
    if (any(lessThan(pc2, inAabb.xy)) || any(greaterThan(pc2, inAabb.zw))) discard;
    ivec2 column = ivec2(pc2);
    vec2 depth;
    if (!columnDepthRange(vec2(column), depth)) discard;

    GpuMaterial m = materials[inMaterial];
    vec4 base = materialBaseColor(m, inUV);
    if (!materialCovers(m, base.a, pc2)) discard;
    vec3 emission = m.emission.rgb;
    if (m.textures.y != NO_TEXTURE) emission *= sampleTexture(m.textures.y, m.textureSizes.zw, inUV).rgb;
    vec3 n = normalize(inNormal);

    // Every voxel layer that the triangle's part inside this pixel column
    // reaches; closed intervals, so a triangle lying exactly on a voxel face
    // marks the voxels on both sides.
    int N = int(grid.dims.x);
    int first = max(int(floor(depth.x - 1e-4)), 0), last = min(int(floor(depth.y + 1e-4)), N - 1);
    // Where in its voxels the triangle can be: its bounding box (the extents, as voxelize.comp ORs them).
    vec3 lo = unswizzle(min(inTri[0], min(inTri[1], inTri[2])), inAxis);
    vec3 hi = unswizzle(max(inTri[0], max(inTri[1], inTri[2])), inAxis);
    for (int layer = first; layer <= last; ++layer) {
        ivec3 voxel = unswizzle(ivec3(column, layer), inAxis);
        uint slot1 = accumulateFragment(voxel, pc.mode.x, base.rgb, emission, n);
        if (slot1 != 0u) atomicOr(voxelExtents[slot1 - 1u], voxelExtentBits(lo - vec3(voxel), hi - vec3(voxel)));
    }
}
