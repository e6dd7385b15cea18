#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "shared/voxel_view_pass.h"

// Voxel debug view: marches each camera ray through the chosen grid (DDA,
// Amanatides & Woo) and shows the first occupied voxel's value, so voxels
// appear as cubes. Faces are shaded slightly by their axis to read the shapes.
// The radiance view shows a two-sided voxel (a wall thinner than a voxel) by
// the side the ray meets, which its radiance texel (the darker side) cannot.
layout(local_size_x = VIEW_GROUP, local_size_y = VIEW_GROUP) in;

layout(set = 0, binding = BIND_VIEW_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_VIEW_FRAME) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = BIND_VIEW_ACCUM, r32f) uniform readonly image3D accum;
layout(set = 0, binding = BIND_VIEW_RADIANCE, rgba16f) uniform readonly image3D radiance;
layout(set = 0, binding = BIND_VIEW_DIRECTIONAL, rgba16f) uniform readonly image3D directional;
layout(set = 0, binding = BIND_VIEW_OUT, rgba32f) uniform writeonly image2D outImage;
layout(set = 0, binding = BIND_VIEW_DIRECT, rgba16f) uniform readonly image3D direct;
layout(set = 0, binding = BIND_VIEW_SIDES, rgba32ui) uniform readonly uimage3D sides;
VOXEL_INDEX_BLOCK(BIND_VIEW_INDEX, readonly);
VOXEL_LIST_BLOCK(BIND_VIEW_LIST, readonly);
layout(push_constant) uniform Push { VoxelViewPush pc; };

#include "lib/voxel_attributes.glsl"
#include "lib/voxel_index.glsl"
#include "lib/voxel_sides.glsl"

vec4 directionalAt(ivec3 v, int size) { return imageLoad(directional, directionalTexel(pc.direction.x, v, size)); }

bool occupied(ivec3 v, uint mode, int size) {
    if (mode == VIEW_RADIANCE) return imageLoad(radiance, v).a > 0.0;
    if (mode == VIEW_DIRECTIONAL) return directionalAt(v, size).a > 0.0;
    return voxelOccupied(v);
}

// Radiance as a ray travelling along rd sees the voxel.
vec3 radianceSeen(ivec3 v, uint slot, vec3 rd) {
    int axis = twoSidedAxis(sideCodeOf(imageLoad(direct, slotTexel(slot, 0u))));
    if (axis < 0) return imageLoad(radiance, v).rgb;
    // A ray travelling toward +axis meets the side facing -axis (side 1).
    return sideLight(imageLoad(sides, slotTexel(slot, 0u)), rd[axis] > 0.0 ? 1 : 0);
}

vec3 value(ivec3 v, uint mode, int size, vec3 rd) {
    uint slot = voxelSlotAt(v) - 1u;  // occupied() held
    if (mode == VIEW_ALBEDO) return voxelAlbedo(slot);
    if (mode == VIEW_NORMAL) return voxelNormal(slot) * 0.5 + 0.5;
    if (mode == VIEW_EMISSION) return voxelEmission(slot);
    if (mode == VIEW_RADIANCE) return radianceSeen(v, slot, rd);
    if (mode == VIEW_AGE) return slot < list.header.counts.y ? vec3(0.30, 0.45, 0.80) : vec3(1.0, 0.55, 0.10);
    return directionalAt(v, size).rgb;
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (px.x >= int(pc.mode.z) || px.y >= int(pc.mode.w)) return;
    uint mode = pc.mode.x;
    int size = int(grid.dims.x);
    if (mode == VIEW_DIRECTIONAL) size = max((size / 2) >> int(pc.mode.y), 1);
    float cell = grid.originSize.w * float(grid.dims.x) / float(size);

    vec2 ndc = (vec2(px) + 0.5) / vec2(pc.mode.zw) * 2.0 - 1.0;
    vec4 a = frame.invViewProj * vec4(ndc, 0.0, 1.0), b = frame.invViewProj * vec4(ndc, 1.0, 1.0);
    vec3 ro = (a.xyz / a.w - grid.originSize.xyz) / cell;  // in cells of the viewed grid
    vec3 rd = normalize(b.xyz / b.w - a.xyz / a.w);
    vec3 inv = 1.0 / (abs(rd) + 1e-20) * sign(rd + 1e-20);
    vec3 t0 = (vec3(0.0) - ro) * inv, t1 = (vec3(float(size)) - ro) * inv;
    float tEnter = max(max(min(t0.x, t1.x), min(t0.y, t1.y)), max(min(t0.z, t1.z), 0.0));
    float tExit = min(min(max(t0.x, t1.x), max(t0.y, t1.y)), max(t0.z, t1.z));
    vec3 color = vec3(0.0);
    if (tEnter < tExit) {
        vec3 p = ro + rd * (tEnter + 1e-4);
        ivec3 v = clamp(ivec3(floor(p)), ivec3(0), ivec3(size - 1));
        ivec3 stepDir = ivec3(sign(rd));
        vec3 tMax = ((vec3(v) + max(vec3(stepDir), 0.0)) - ro) * inv;
        vec3 tDelta = abs(inv);
        int axis = 0;
        {
            vec3 tn = min(t0, t1);
            axis = tn.x >= tn.y && tn.x >= tn.z ? 0 : (tn.y >= tn.z ? 1 : 2);
        }
        for (int i = 0; i < 3 * size; ++i) {
            if (occupied(v, mode, size)) {
                color = value(v, mode, size, rd) * (axis == 0 ? 0.8 : (axis == 1 ? 1.0 : 0.9));
                break;
            }
            if (tMax.x < tMax.y && tMax.x < tMax.z) { v.x += stepDir.x; tMax.x += tDelta.x; axis = 0; }
            else if (tMax.y < tMax.z) { v.y += stepDir.y; tMax.y += tDelta.y; axis = 1; }
            else { v.z += stepDir.z; tMax.z += tDelta.z; axis = 2; }
            if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, ivec3(size)))) break;
        }
    }
    imageStore(outImage, px, vec4(color, 1.0));
}
