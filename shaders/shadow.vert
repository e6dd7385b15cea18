#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/geometry_pass.h"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUV;

layout(set = 0, binding = BIND_GEOM_DRAWS, std430) readonly buffer Draws { GpuDraw draws[]; };
layout(set = 0, binding = BIND_GEOM_SHADOW_VIEWS, std430) readonly buffer Views { GpuShadowView views[]; };
layout(push_constant) uniform Push { DrawPush pc; };

layout(location = 0) out vec2 outUV;
layout(location = 1) flat out uint outMaterial;

void main() {
    GpuDraw draw = draws[pc.ids.x];
    outUV = inUV;
    outMaterial = draw.info.x;
    gl_Position = views[pc.ids.y].viewProj * (draw.model * vec4(inPosition, 1.0));
}
