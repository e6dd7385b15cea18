#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/voxel_data.h"
#include "shared/voxelize_pass.h"
#include "shared/voxel_list_pass.h"

// Projects each triangle along its dominant axis onto an N x N viewport (one
// pixel per voxel column) and, without hardware conservative rasterization,
// dilates it by half a pixel (Hasselgren et al., GPU Gems 2 ch. 42): every
// edge moves outward by half the pixel's extent along the edge normal. The
// fragment shader clips the over-grown corners with the triangle's AABB.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

layout(set = 0, binding = BIND_VOX_GRID) uniform Grid { VoxelGrid grid; };
layout(push_constant) uniform Push { VoxelizePush pc; };

layout(location = 0) in vec3 inVoxel[];
layout(location = 1) in vec3 inNormal[];
layout(location = 2) in vec2 inUV[];
layout(location = 3) flat in uint inMaterial[];

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec2 outUV;
layout(location = 2) flat out uint outMaterial;
layout(location = 3) flat out uint outAxis;
layout(location = 4) flat out vec4 outAabb;    // xy min, zw max (pixels), already grown by half a pixel
layout(location = 5) flat out vec3 outTri[3];  // the projected triangle: xy pixels, z depth (voxel units)

#include "lib/voxel_window.glsl"

// Half a pixel plus a margin (VoxelizePush.mode.z, float bits) of two steps
// of the rasterizer's sub-pixel grid. Vertices are snapped to that grid, so a
// triangle that only touches a pixel's border, or passes within a snap step of
// it, must still be dilated past the pixel centre after snapping, where the
// top-left rule would otherwise drop the tie (closed-box overlap, as the CPU
// reference defines it, needs those pixels).
float grow() { return 0.5 + uintBitsToFloat(pc.mode.z); }

vec3 swizzle(vec3 p, uint axis) {
    return axis == 0u ? p.yzx : (axis == 1u ? p.zxy : p.xyz);
}

vec2 lineIntersection(vec3 l0, vec3 l1) {  // lines n.x*x + n.y*y = d, stored as (n, d)
    float det = l0.x * l1.y - l0.y * l1.x;
    return vec2(l0.z * l1.y - l0.y * l1.z, l0.x * l1.z - l0.z * l1.x) / det;
}

void main() {
    vec3 faceNormal = cross(inVoxel[1] - inVoxel[0], inVoxel[2] - inVoxel[0]);
    vec3 an = abs(faceNormal);
    if (max(an.x, max(an.y, an.z)) < 1e-12) return;  // degenerate triangle
    // After a clipmap scroll, static voxelization skips a triangle whose
    // dilated box lies in the part of the window the scroll kept.
    vec3 lo3 = min(inVoxel[0], min(inVoxel[1], inVoxel[2])), hi3 = max(inVoxel[0], max(inVoxel[1], inVoxel[2]));
    if (pc.mode.x != VOXELIZE_DYNAMIC && rangeKeptByScroll(ivec3(floor(lo3)) - 1, ivec3(floor(hi3)) + 1)) return;
    uint axis = (an.x >= an.y && an.x >= an.z) ? 0u : (an.y >= an.z ? 1u : 2u);

    vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = swizzle(inVoxel[i], axis);

    vec2 lo = min(q[0].xy, min(q[1].xy, q[2].xy)), hi = max(q[0].xy, max(q[1].xy, q[2].xy));
    const float GROW = grow();
    outAabb = vec4(lo - GROW, hi + GROW);
    outTri = q;
    outAxis = axis;
    outMaterial = inMaterial[0];

    vec2 v[3] = vec2[3](q[0].xy, q[1].xy, q[2].xy);
    if (pc.mode.y != 0u) {
        // Counter-clockwise order (y up) so (e.y, -e.x) is the outward normal.
        float area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
        bool flip = area < 0.0;
        vec2 w[3] = flip ? vec2[3](v[0], v[2], v[1]) : v;
        vec3 lines[3];
        for (int i = 0; i < 3; ++i) {
            vec2 e = w[(i + 1) % 3] - w[i];
            vec2 en = normalize(vec2(e.y, -e.x));
            lines[i] = vec3(en, dot(en, w[i]) + GROW * (abs(en.x) + abs(en.y)));
        }
        vec2 grown[3];
        for (int i = 0; i < 3; ++i) grown[i] = lineIntersection(lines[(i + 2) % 3], lines[i]);
        v = flip ? vec2[3](grown[0], grown[2], grown[1]) : grown;
    }

    // Attributes at the (possibly moved) vertices: extrapolate with the
    // barycentric coordinates of the new positions in the original triangle.
    vec2 e1 = q[1].xy - q[0].xy, e2 = q[2].xy - q[0].xy;
    float det = e1.x * e2.y - e1.y * e2.x;
    for (int i = 0; i < 3; ++i) {
        vec2 d = v[i] - q[0].xy;
        float b1 = (d.x * e2.y - d.y * e2.x) / det, b2 = (e1.x * d.y - e1.y * d.x) / det;
        float b0 = 1.0 - b1 - b2;
        outNormal = b0 * inNormal[0] + b1 * inNormal[1] + b2 * inNormal[2];
        outUV = b0 * inUV[0] + b1 * inUV[1] + b2 * inUV[2];
        float N = float(grid.dims.x);
        gl_Position = vec4(v[i] / N * 2.0 - 1.0, 0.5, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
