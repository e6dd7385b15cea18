#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
#include "shared/scene_data.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "shared/voxelize_pass.h"
#include "shared/pv_pass.h"

// Progressive voxelization, injection (shared/pv_pass.h): each sample of the
// camera's G-buffer on the injection grid puts its surface point's material
// into the voxel holding it, claiming the voxel when it is new. Samples of
// one voxel average, as fragments do in the geometric voxelizers.
layout(local_size_x = PV_INJECT_GROUP, local_size_y = PV_INJECT_GROUP) in;

layout(set = 0, binding = BIND_PV_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_PV_ACCUM, r32f) uniform coherent image3D accum;
VOXEL_LIST_BLOCK(BIND_PV_LIST, );
VOXEL_INDEX_BLOCK(BIND_PV_INDEX, coherent);
layout(set = 0, binding = BIND_PV_FRAME) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = BIND_PV_CAMERA_DEPTH) uniform sampler2D depthBuffer;
layout(set = 0, binding = BIND_PV_GBUFFER_BASE) uniform sampler2D baseBuffer;
layout(set = 0, binding = BIND_PV_GBUFFER_NORMAL) uniform sampler2D normalBuffer;
layout(set = 0, binding = BIND_PV_GBUFFER_EMISSION) uniform sampler2D emissionBuffer;
layout(push_constant) uniform Push { PvInjectPush pc; };

#include "lib/voxel_index.glsl"
#include "lib/voxel_accumulate.glsl"

vec3 unproject(vec2 ndc, float depth) {
    vec4 p = frame.invViewProj * vec4(ndc, depth, 1.0);
    return p.xyz / p.w;
}

void main() {
    uvec2 cell = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(cell, pc.sizes.zw))) return;
    // The pixel nearest the centre of the injection cell.
    vec2 size = vec2(pc.sizes.xy), cellSize = size / vec2(pc.sizes.zw);
    ivec2 pixel = ivec2(min((vec2(cell) + 0.5) * cellSize, size - 1.0));
    vec4 emission = texelFetch(emissionBuffer, pixel, 0);
    float depth = texelFetch(depthBuffer, pixel, 0).r;
    if (emission.a == 0.0 || depth >= 1.0) return;  // background
    vec2 ndc = (vec2(pixel) + 0.5) / size * 2.0 - 1.0;
    vec3 p = unproject(ndc, depth);
    float voxelSize = grid.originSize.w;
    ivec3 voxel = ivec3(floor((p - grid.originSize.xyz) / voxelSize));
    vec3 base = texelFetch(baseBuffer, pixel, 0).rgb;
    vec3 n = texelFetch(normalBuffer, pixel, 0).xyz;
    // The sample stands for the surface its cell covers: the corners of the
    // cell's footprint on the tangent plane also get it, so that a voxel the
    // surface only clips (the geometric voxelizers mark every voxel a surface
    // touches) is found without waiting for a pixel centre to land in it.
    // Corners farther than a voxel (grazing views) are left out.
    ivec3 done[5];
    int count = 0;
    for (int k = 0; k < 5; ++k) {
        ivec3 v = voxel;
        if (k > 0) {
            vec2 corner = (vec2(cell) + vec2((k - 1) & 1, (k - 1) >> 1)) * cellSize;
            vec2 c = corner / size * 2.0 - 1.0;
            vec3 o = unproject(c, 0.0), d = unproject(c, 1.0) - o;
            float dn = dot(d, n);
            if (abs(dn) < 1e-12) continue;
            vec3 x = o + d * (dot(p - o, n) / dn);
            if (distance(x, p) > voxelSize) continue;
            v = ivec3(floor((x - grid.originSize.xyz) / voxelSize));
        }
        if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, ivec3(grid.dims.x)))) continue;
        bool seen = false;
        for (int j = 0; j < count; ++j) seen = seen || all(equal(done[j], v));
        if (seen) continue;
        done[count++] = v;
        accumulateFragment(v, VOXELIZE_STATIC, base, emission.rgb, n);
    }
}
