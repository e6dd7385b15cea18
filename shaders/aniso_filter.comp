#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/aniso_filter_pass.h"
#include "shared/voxel_data.h"

// Anisotropic filtering (paper section VII). Each target voxel covers 2x2x2
// source voxels. For each of the six travel directions, the four child columns
// along that axis are composited front to back (front + back * (1 - front.a),
// "front" = the child a ray travelling that way enters first) and averaged.
// The base level reads the radiance volume for all six directions; each upper
// level reads the same direction's previous level.
layout(local_size_x = ANISO_GROUP, local_size_y = ANISO_GROUP, local_size_z = ANISO_GROUP) in;

layout(set = 0, binding = BIND_ANISO_SOURCE, rgba16f) uniform readonly image3D source;
layout(set = 0, binding = BIND_ANISO_SOURCE_DIRS, rgba16f) uniform readonly image3D sourceDirs;
layout(set = 0, binding = BIND_ANISO_TARGET_DIRS, rgba16f) uniform writeonly image3D targetDirs;
layout(push_constant) uniform Push { AnisoPush pc; };

vec4 child(uint dir, ivec3 p) {
    return pc.sizes.y != 0u ? imageLoad(source, p) : imageLoad(sourceDirs, directionalTexel(dir, p, 2 * int(pc.sizes.x)));
}

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, ivec3(pc.sizes.x)))) return;
    ivec3 base = v * 2;
    int size = int(pc.sizes.x);
    // Most of a grid is empty. Where the eight children of one direction are
    // all zero, so are the other five's (each is a composite of the same
    // voxels) and every result: eight loads decide it instead of the 48 below.
    // Empty regions are large, so whole SIMD groups take this branch together.
    bool empty = true;
    for (int i = 0; i < 8; ++i)
        empty = empty && all(equal(child(0u, base + ivec3(i & 1, (i >> 1) & 1, i >> 2)), vec4(0.0)));
    if (empty) {
        for (uint dir = 0u; dir < DIRECTIONAL_VOLUMES; ++dir) imageStore(targetDirs, directionalTexel(dir, v, size), vec4(0.0));
        return;
    }
    for (uint dir = 0u; dir < DIRECTIONAL_VOLUMES; ++dir) {
        int axis = int(dir / 2u);
        // Travelling toward -axis (even dir) the ray enters the +axis child first.
        int frontOffset = (dir % 2u == 0u) ? 1 : 0;
        vec4 sum = vec4(0.0);
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) {
                ivec3 front = ivec3(0), back = ivec3(0);
                // (a, b) index the two axes other than `axis`.
                int u = (axis + 1) % 3, w = (axis + 2) % 3;
                front[u] = a; front[w] = b; front[axis] = frontOffset;
                back[u] = a; back[w] = b; back[axis] = 1 - frontOffset;
                vec4 f = child(dir, base + front), k = child(dir, base + back);
                sum += f + k * (1.0 - f.a);
            }
        imageStore(targetDirs, directionalTexel(dir, v, size), sum * 0.25);
    }
}
