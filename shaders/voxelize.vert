#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/voxel_data.h"
#include "shared/voxelize_pass.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUV;

layout(set = 0, binding = BIND_VOX_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_VOX_DRAWS, std430) readonly buffer Draws { GpuDraw draws[]; };
layout(push_constant) uniform Push { VoxelizePush pc; };

layout(location = 0) out vec3 outVoxel;  // position in voxel units: 0..N across the grid
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUV;
layout(location = 3) flat out uint outMaterial;

void main() {
    GpuDraw draw = draws[pc.ids.x];
    vec3 world = (draw.model * vec4(inPosition, 1.0)).xyz;
    outVoxel = (world - grid.originSize.xyz) / grid.originSize.w;
    outNormal = mat3(draw.normalMatrix) * inNormal;
    outUV = inUV;
    outMaterial = draw.info.x;
    gl_Position = vec4(0.0);  // the geometry shader projects
}
