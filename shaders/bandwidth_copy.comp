#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/bandwidth_copy_pass.h"

// Streams one storage buffer into another, 16 bytes per load and store: the
// simplest kernel whose speed is the memory system's, which the bench divides
// every pass's modelled traffic by. A grid-stride loop keeps the dispatch
// within the workgroup-count limit for buffers of any size.
layout(local_size_x = COPY_GROUP) in;

layout(set = 0, binding = BIND_COPY_SRC, std430) readonly buffer Src { uvec4 src[]; };
layout(set = 0, binding = BIND_COPY_DST, std430) writeonly buffer Dst { uvec4 dst[]; };
layout(push_constant) uniform Push { CopyPush pc; };

void main() {
    uint stride = gl_NumWorkGroups.x * COPY_GROUP;
    for (uint i = gl_GlobalInvocationID.x; i < pc.sizes.x; i += stride) dst[i] = src[i];
}
