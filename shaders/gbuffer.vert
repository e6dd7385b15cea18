#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/geometry_pass.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUV;
layout(location = 3) in vec4 inTangent;

layout(set = 0, binding = BIND_GEOM_FRAME) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = BIND_GEOM_DRAWS, std430) readonly buffer Draws { GpuDraw draws[]; };
layout(push_constant) uniform Push { DrawPush pc; };

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec2 outUV;
layout(location = 2) flat out uint outMaterial;

void main() {
    GpuDraw draw = draws[pc.ids.x];
    vec4 world = draw.model * vec4(inPosition, 1.0);
    outNormal = mat3(draw.normalMatrix) * inNormal;
    outUV = inUV;
    outMaterial = draw.info.x;
    gl_Position = frame.viewProj * world;
}
