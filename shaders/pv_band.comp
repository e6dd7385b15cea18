#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
#include "shared/scene_data.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "shared/voxelize_pass.h"
#include "shared/pv_pass.h"

// Progressive voxelization, single-pass injection (shared/pv_pass.h): voxels
// find their samples instead of samples finding their voxels. Every voxel
// whose centre lies in the depth band of a G-buffer (the recorded surface
// within the voxel's half-diagonal along the ray through the centre) takes the
// sample of the pixel it projects to. Cheaper per sample than splatting and
// independent of the image size, but a voxel that a surface only clips, with
// its centre's ray passing beside it, is not found.
layout(local_size_x = PV_BAND_GROUP, local_size_y = PV_BAND_GROUP, local_size_z = PV_BAND_GROUP) in;

layout(set = 0, binding = BIND_PV_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_PV_ACCUM, r32f) uniform coherent image3D accum;
VOXEL_LIST_BLOCK(BIND_PV_LIST, );
VOXEL_INDEX_BLOCK(BIND_PV_INDEX, coherent);
layout(set = 0, binding = BIND_PV_FRAME) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = BIND_PV_CAMERA_DEPTH) uniform sampler2D depthBuffer;
layout(set = 0, binding = BIND_PV_GBUFFER_BASE) uniform sampler2D baseBuffer;
layout(set = 0, binding = BIND_PV_GBUFFER_NORMAL) uniform sampler2D normalBuffer;
layout(set = 0, binding = BIND_PV_GBUFFER_EMISSION) uniform sampler2D emissionBuffer;
layout(push_constant) uniform Push { PvBandPush pc; };

#include "lib/voxel_index.glsl"
#include "lib/voxel_accumulate.glsl"
#include "lib/pv_project.glsl"

void main() {
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, ivec3(grid.dims.x)))) return;
    vec3 c = grid.originSize.xyz + (vec3(voxel) + 0.5) * grid.originSize.w;
    vec4 clip;
    vec3 ndc;
    if (!projectInView(frame.viewProj, c, clip, ndc)) return;
    ivec2 pixel = ndcPixel(ndc.xy, ivec2(pc.sizes.xy));
    vec4 emission = texelFetch(emissionBuffer, pixel, 0);
    float depth = texelFetch(depthBuffer, pixel, 0).r;
    if (emission.a == 0.0 || depth >= 1.0) return;  // background: the cleanup frees what lies there
    if (distance(unprojectNdc(frame.invViewProj, ndc.xy, depth), c) > pc.params.x) return;
    vec3 base = texelFetch(baseBuffer, pixel, 0).rgb;
    vec3 n = texelFetch(normalBuffer, pixel, 0).xyz;
    accumulateFragment(voxel, VOXELIZE_STATIC, base, emission.rgb, n);
}
