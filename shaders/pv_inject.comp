#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
#include "shared/scene_data.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "shared/voxelize_pass.h"
#include "shared/pv_pass.h"
#include "shared/voxelize_compute_pass.h"

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

#include "lib/pv_project.glsl"

vec3 unproject(vec2 ndc, float depth) { return unprojectNdc(frame.invViewProj, ndc, depth); }

// Whether axis `a` separates the quad q (voxel units, relative to a voxel's
// centre) from that voxel, grown like the geometric voxelizers' boxes.
bool separates(vec3 a, vec3 q[4]) {
    float lo = dot(q[0], a), hi = lo;
    for (int k = 1; k < 4; ++k) {
        float d = dot(q[k], a);
        lo = min(lo, d);
        hi = max(hi, d);
    }
    float r = (0.5 + VOXC_BOX_GROWTH) * (abs(a.x) + abs(a.y) + abs(a.z));
    return lo > r || hi < -r;
}

// Separating-axis test of a planar convex quad against the voxel at the
// origin: the box's three axes, the quad's normal, and each quad edge
// crossed with each box axis.
bool quadTouchesVoxel(vec3 q[4], vec3 n) {
    for (int i = 0; i < 3; ++i) {
        vec3 axis = vec3(0.0);
        axis[i] = 1.0;
        if (separates(axis, q)) return false;
    }
    if (separates(n, q)) return false;
    for (int k = 0; k < 4; ++k) {
        vec3 e = q[(k + 1) % 4] - q[k];
        for (int i = 0; i < 3; ++i) {
            vec3 axis = vec3(0.0);
            axis[i] = 1.0;
            vec3 c = cross(e, axis);
            if (dot(c, c) > 1e-12 && separates(c, q)) return false;
        }
    }
    return true;
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
    float voxelSize = grid.originSize.w;
    // Voxel units from here on.
    vec3 p = (unproject(ndc, depth) - grid.originSize.xyz) / voxelSize;
    ivec3 voxel = ivec3(floor(p));
    vec3 base = texelFetch(baseBuffer, pixel, 0).rgb;
    vec3 n = texelFetch(normalBuffer, pixel, 0).xyz;
    // The sample stands for the surface its cell covers: the cell's footprint
    // on the tangent plane, a convex quad, gets it in every voxel it touches
    // (as the geometric voxelizers mark every voxel a surface touches), so a
    // voxel the surface only clips is found without waiting for a pixel
    // centre to land in it. A footprint reaching more than a voxel from the
    // sample (grazing views) falls back to the sample's own voxel.
    vec3 q[4];
    bool footprint = true;
    for (int k = 0; k < 4; ++k) {
        // Corners in order around the cell: (0,0), (1,0), (1,1), (0,1).
        vec2 corner = (vec2(cell) + vec2(k == 1 || k == 2 ? 1.0 : 0.0, k >= 2 ? 1.0 : 0.0)) * cellSize;
        vec2 c = corner / size * 2.0 - 1.0;
        vec3 o = (unproject(c, 0.0) - grid.originSize.xyz) / voxelSize;
        vec3 d = (unproject(c, 1.0) - grid.originSize.xyz) / voxelSize - o;
        float dn = dot(d, n);
        if (abs(dn) < 1e-12) {
            footprint = false;
            break;
        }
        q[k] = o + d * (dot(p - o, n) / dn);
        if (any(greaterThan(abs(q[k] - p), vec3(1.0)))) {
            footprint = false;
            break;
        }
    }
    ivec3 lo = voxel, hi = voxel;
    if (footprint) {
        vec3 qlo = min(min(q[0], q[1]), min(q[2], q[3])), qhi = max(max(q[0], q[1]), max(q[2], q[3]));
        lo = ivec3(floor(qlo - VOXC_BOX_GROWTH));
        hi = ivec3(floor(qhi + VOXC_BOX_GROWTH));
    }
    lo = max(lo, ivec3(0));
    hi = min(hi, ivec3(int(grid.dims.x) - 1));
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                ivec3 v = ivec3(x, y, z);
                if (footprint) {
                    vec3 r[4];
                    for (int k = 0; k < 4; ++k) r[k] = q[k] - (vec3(v) + 0.5);
                    if (!quadTouchesVoxel(r, n)) continue;
                } else if (v != voxel) {
                    continue;
                }
                accumulateFragment(v, VOXELIZE_STATIC, base, emission.rgb, n);
            }
}
