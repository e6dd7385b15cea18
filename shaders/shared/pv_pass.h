// Progressive screen-space voxelization (Gaitatzes & Papaioannou, seed 004;
// vxgi/pv_voxelize.cpp, pv_cleanup.comp, pv_inject.comp): the voxel volumes
// are kept from frame to frame and updated from the image buffers the frame
// already has. Shared by C++ and GLSL.
#ifndef DVSGI_SHARED_PV_PASS_H
#define DVSGI_SHARED_PV_PASS_H

#include "common.h"

DVSGI_BEGIN

// A depth buffer that can prove voxels empty: the camera's depth (layer
// PV_CAMERA_LAYER) or one layer of the shadow-map array.
struct PvDepthView {
    mat4 viewProj;
    mat4 invViewProj;
    vec4 params;  // x shadow-map layer or PV_CAMERA_LAYER, y tolerance added to the voxel's (m),
                  // z tolerance per metre of view depth (perspective shadow views), w unused
};
DVSGI_CHECK_SIZE(PvDepthView, 144);
DVSGI_CONST(float, PV_CAMERA_LAYER, -1.0);

// Cleanup, one invocation per entry of last frame's list (VOXEL_LIST_GROUP per
// workgroup): every voxel centre is projected into each depth view; a voxel in
// front of the recorded depth by more than its tolerance (the voxel's half
// diagonal plus the view's own) is empty and freed. A survivor moves to the
// next slot of the new list with its sums; one the camera sees in the depth
// band keeps them at most PvCleanupPush.weights.x fragments' worth, so this
// frame's samples replace what it held (the chapter's update).
struct PvCleanupPush {
    uvec4 sizes;    // x depth views, y camera depth width, z height, w shadow-map size
    vec4 weights;   // x weight kept by a voxel in the camera's band, y weight kept by any other
                    // survivor (bounds the sums), z the voxel's tolerance (m): half its diagonal
};
DVSGI_CHECK_SIZE(PvCleanupPush, 32);

// Injection, one invocation per sample of the camera's G-buffer on the
// injection grid (PV_INJECT_GROUP^2 per workgroup): the surface point
// recovered from depth adds the pixel's material to its voxel, through the
// same accumulation the geometric voxelizers use.
DVSGI_CONST(uint, PV_INJECT_GROUP, 8);
struct PvInjectPush {
    uvec4 sizes;  // x G-buffer width, y height, z injection grid width, w height
};
DVSGI_CHECK_SIZE(PvInjectPush, 16);

// Single-pass injection (--pv-single-pass, the chapter's section 6.2.3): one
// invocation per grid voxel (PV_BAND_GROUP^3 per workgroup) projects the voxel
// centre into a G-buffer and, when the recorded surface lies within the
// tolerance of it along the ray, turns the voxel on with that pixel's sample.
DVSGI_CONST(uint, PV_BAND_GROUP, 4);
struct PvBandPush {
    uvec4 sizes;  // x G-buffer width, y height
    vec4 params;  // x tolerance (m): the voxel's half-diagonal
};
DVSGI_CHECK_SIZE(PvBandPush, 32);

DVSGI_CONST(uint, BIND_PV_GRID, 0);
DVSGI_CONST(uint, BIND_PV_ACCUM, 1);           // this frame's sums (written)
DVSGI_CONST(uint, BIND_PV_LIST, 2);            // this frame's list (appended)
DVSGI_CONST(uint, BIND_PV_INDEX, 3);
DVSGI_CONST(uint, BIND_PV_RADIANCE, 4);        // cleanup: zeroed where a voxel is freed
DVSGI_CONST(uint, BIND_PV_OLD_ACCUM, 5);       // cleanup: last frame's sums
DVSGI_CONST(uint, BIND_PV_OLD_LIST, 6);        // cleanup: last frame's list
DVSGI_CONST(uint, BIND_PV_VIEWS, 7);           // cleanup: PvDepthView[]
DVSGI_CONST(uint, BIND_PV_CAMERA_DEPTH, 8);    // D32, point sampler
DVSGI_CONST(uint, BIND_PV_SHADOW_DEPTH, 9);    // cleanup: D32 array, point sampler
DVSGI_CONST(uint, BIND_PV_FRAME, 10);          // injection: FrameConstants (inverse view-projection)
DVSGI_CONST(uint, BIND_PV_GBUFFER_BASE, 11);   // injection: base colour
DVSGI_CONST(uint, BIND_PV_GBUFFER_NORMAL, 12);
DVSGI_CONST(uint, BIND_PV_GBUFFER_EMISSION, 13);

DVSGI_END

#endif
