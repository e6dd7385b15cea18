// Compute voxelization (vxgi/voxelize_compute.cpp, voxelize.comp): triangles
// binned to voxels with an exact triangle/box test; shared by C++ and GLSL.
#ifndef DVSGI_SHARED_VOXELIZE_COMPUTE_PASS_H
#define DVSGI_SHARED_VOXELIZE_COMPUTE_PASS_H

#include "common.h"

DVSGI_BEGIN

// One invocation per triangle in the triangle phase, one per run of columns of
// a tile's row in the tile phase: both use groups of VOXC_GROUP = VOXC_TILE^2.
DVSGI_CONST(uint, VOXC_GROUP, 64);
DVSGI_CONST(uint, VOXC_TILE, 8);
// A triangle whose (grid-clipped) footprint along its dominant axis spans more
// voxel columns than the walk threshold is split into tiles, one workgroup
// each, instead of being walked by its one invocation (a Cornell wall at 128^3
// is 16384 columns: serial, it would hold the whole dispatch back). A tile is
// VOXC_TILE rows of VOXC_TILE invocations, each walking a run of consecutive
// columns of its row. On a GPU lanes are cheap and divergence is not: small
// tiles, one column per lane. A CPU device pays for every lane (each loads
// the triangle) and little for divergence: longer walks, eight columns per
// lane. Measured on lavapipe, Sponza 256^3: 32 walk columns took 1.4-1.6x as
// long as 256, one column per lane 1.2x as long as eight, and the Cornell box
// at 128^3 2.3x (docs/benchmarks.md, "The compute voxelizer on a CPU device"
// and "Deferred samples and longer tile lanes on CPU devices").
DVSGI_CONST(uint, VOXC_WALK_COLUMNS_GPU, 32);
DVSGI_CONST(uint, VOXC_LANE_COLUMNS_GPU, 1);
DVSGI_CONST(uint, VOXC_WALK_COLUMNS_CPU, 256);
DVSGI_CONST(uint, VOXC_LANE_COLUMNS_CPU, 8);
// llvmpipe ends every loop of an invocation once its loops together have
// looped 65535 times (test LavapipeLimits.LoopsShareOneIterationBudget): the
// rest of a walk would be dropped without an error. A walk loops once per
// candidate (at most four a column: the plane spans two layers over a column,
// plus the rounding margin) and, per hit, about a dozen times in the sample's
// loops (textures, taps, the voxel claim); the CPU tiling stays far under the
// budget (static_assert in vxgi/voxelize_compute.cpp). Two walks are not
// bounded by it: a degenerate triangle's, which tries every layer of its box,
// and the walk of a triangle whose tiles no longer fit the queue; on llvmpipe
// either could lose voxels on a large grid.
DVSGI_CONST(uint, LLVMPIPE_LOOP_BUDGET, 65535);
DVSGI_CONST(uint, VOXC_CANDIDATES_PER_COLUMN, 4);
DVSGI_CONST(uint, VOXC_LOOPS_PER_SAMPLE, 12);
DVSGI_CONST(uint, VOXC_WALK_LOOPS_PER_COLUMN, VOXC_CANDIDATES_PER_COLUMN * (1 + VOXC_LOOPS_PER_SAMPLE));
// Hits a walk collects before it samples them (voxelize.comp, walkColumns):
// on llvmpipe, which runs an if's body under a mask for every candidate, up
// to VOXC_PENDING; on GPUs one, sampled as soon as it is found, as measured
// on the H200 before (a private array indexed per lane would live in memory
// there). The push constant's tiling.z picks it.
DVSGI_CONST(uint, VOXC_PENDING, 32);
DVSGI_CONST(uint, VOXC_PENDING_GPU, 1);
// Most columns one tile invocation may walk (ComputeTiling::laneColumns).
DVSGI_CONST(uint, VOXC_MAX_LANE_COLUMNS, 64);
// Tile work items one triangle phase can queue (16 MiB of VoxcTile). A
// triangle whose tiles no longer fit is walked by its own invocation: slower,
// same result. 65535 (the old bound, one dispatch row) overflowed on Sponza at
// 512^3, where the serial walks took 0.58 s on an H200.
DVSGI_CONST(uint, VOXC_MAX_TILES, 1u << 20);
// The tile phase's indirect dispatch is VOXC_TILE_ROW workgroups wide (the
// least maxComputeWorkGroupCount[0] Vulkan allows) and as many rows high as
// the queued tiles need. Its buffer: x = min(tiles, VOXC_TILE_ROW), y = rows,
// z = 1, w = tiles queued.
DVSGI_CONST(uint, VOXC_TILE_ROW, 65535);

DVSGI_CONST(uint, VOXC_PHASE_TRIANGLES, 0);
DVSGI_CONST(uint, VOXC_PHASE_TILES, 1);

// One workgroup of the triangle phase: up to VOXC_GROUP consecutive triangles
// of one draw, so the material (and its texture index) is uniform within the
// workgroup, as Vulkan requires without non-uniform descriptor indexing.
struct VoxcGroup {
    uvec4 draw;  // x draw index, y first index of the group's first triangle, z vertex offset (int bits),
                 // w triangles in the group (1..VOXC_GROUP)
};
DVSGI_CHECK_SIZE(VoxcGroup, 16);

// A queued tile: x draw, y first index of the triangle, z vertex offset (int
// bits), w tile index (row-major over the triangle's footprint).
struct VoxcTile {
    uvec4 item;
};
DVSGI_CHECK_SIZE(VoxcTile, 16);

struct VoxelizeComputePush {
    uvec4 ids;  // x first VoxcGroup of this mode, y group count, z VOXELIZE_STATIC/DYNAMIC, w VOXC_PHASE_*
    uvec4 dispatch;  // x workgroups per row of a 2D triangle-phase dispatch (groups beyond 65535 wrap into y),
                     // y = 4 (bilinear taps), z = 2 (textures per material; 1 when no material has an
                     // emissive texture): loop counts the shader compiler must not see, so each
                     // texture fetch stays one site (lib/material.glsl)
    uvec4 tiling;    // x the most columns a triangle walks alone (VOXC_WALK_COLUMNS_*),
                     // y columns per invocation in a tile (VOXC_LANE_COLUMNS_*),
                     // z hits a walk collects before sampling them (1..VOXC_PENDING)
};
DVSGI_CHECK_SIZE(VoxelizeComputePush, 48);

DVSGI_CONST(uint, BIND_VOXC_GRID, 0);
DVSGI_CONST(uint, BIND_VOXC_DRAWS, 1);
DVSGI_CONST(uint, BIND_VOXC_MATERIALS, 2);
DVSGI_CONST(uint, BIND_VOXC_ACCUM, 3);
DVSGI_CONST(uint, BIND_VOXC_INDEX, 4);
DVSGI_CONST(uint, BIND_VOXC_VERTICES, 5);  // scene::Vertex, VOXC_VERTEX_FLOATS floats each
DVSGI_CONST(uint, BIND_VOXC_INDICES, 6);
DVSGI_CONST(uint, BIND_VOXC_GROUPS, 7);
DVSGI_CONST(uint, BIND_VOXC_TILES, 8);     // VoxcTile[VOXC_MAX_TILES]
DVSGI_CONST(uint, BIND_VOXC_LIST, 10);     // occupied-voxel list (appended to)
DVSGI_CONST(uint, BIND_VOXC_INDIRECT, 9);  // uint[4]: the tile phase's dispatch (see VOXC_TILE_ROW)
DVSGI_CONST(uint, BIND_VOXC_EXTENTS, 11);  // per-slot extents (voxel_data.h), OR-ed into

// scene::Vertex as floats: position 0-2, normal 3-5, uv 6-7, tangent 8-11.
DVSGI_CONST(uint, VOXC_VERTEX_FLOATS, 12);

// Voxel boxes are grown by this much (voxel units) on every side before the
// exact test, so a triangle that lies on a voxel face up to the float rounding
// of its transform marks the voxels on both sides, as the raster path's closed
// intervals do (a wall then stays two layers thick wherever rounding puts it).
DVSGI_CONST(float, VOXC_BOX_GROWTH, 1e-4);

DVSGI_END

#endif
