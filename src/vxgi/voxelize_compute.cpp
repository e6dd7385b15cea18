#include "vxgi/voxelize_compute.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>
#include <vector>

#include "gpu/context.h"
#include "gpu/tracker.h"
#include "gpu/transfer.h"
#include "gpuscene/scene_gpu.h"
#include "shared/geometry_pass.h"
#include "shared/voxelize_compute_pass.h"
#include "shared/voxelize_pass.h"
#include "vxgi/volumes.h"
#include "vxgi/voxelize.h"

namespace dvsgi::vxgi {

namespace {

namespace sh = dvsgi::shader;

const uint32_t kComp[] = {
#include "shaders/voxelize.comp.inc"
};

// A group's triangles are one chunk of SceneGpu::primitiveChunks.
static_assert(gpuscene::SceneGpu::kBoundsChunk == sh::VOXC_GROUP);

// Groups of up to VOXC_GROUP consecutive triangles, never two draws in one.
void appendGroups(const gpuscene::SceneGpu& scene, bool dynamic, std::vector<sh::VoxcGroup>& out) {
    for (uint32_t d = 0; d < scene.ranges.size(); ++d) {
        const gpuscene::DrawRange& r = scene.ranges[d];
        if (r.dynamic != dynamic) continue;
        const uint32_t triangles = r.indexCount / 3;
        for (uint32_t first = 0; first < triangles; first += sh::VOXC_GROUP)
            out.push_back({glm::uvec4(d, r.firstIndex + 3 * first, std::bit_cast<uint32_t>(r.vertexOffset),
                                      std::min(sh::VOXC_GROUP, triangles - first))});
    }
}

}  // namespace

// llvmpipe would cut a longer walk short (shared/voxelize_compute_pass.h).
static_assert(uint64_t(sh::VOXC_WALK_COLUMNS_CPU) * sh::VOXC_WALK_LOOPS_PER_COLUMN < sh::LLVMPIPE_LOOP_BUDGET / 2);
static_assert(uint64_t(sh::VOXC_LANE_COLUMNS_CPU) * sh::VOXC_WALK_LOOPS_PER_COLUMN < sh::LLVMPIPE_LOOP_BUDGET / 2);

void chunkWorldBounds(const scene::Bounds& local, const glm::mat4& world, glm::vec3& lo, glm::vec3& hi) {
    lo = glm::vec3(1e30f);
    hi = glm::vec3(-1e30f);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 w = glm::vec3(world * glm::vec4(local.corner(c), 1.0f));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
    }
}

bool groupReachesWrittenVoxels(const glm::vec3& lo, const glm::vec3& hi, const GridSpec& grid, const glm::ivec4& keep) {
    // The shader's closed box of each triangle (ceil(lo - growth) - 1 ..
    // floor(hi + growth)), grown by two more voxels for the rounding between
    // these float bounds and its own; clamped in float first, so far-away or
    // unset bounds cannot overflow the conversion to int.
    const int n = int(grid.n);
    const glm::vec3 limit(float(n) + 8.0f);
    const glm::vec3 fa = glm::clamp(glm::floor((lo - grid.origin) / grid.voxelSize), -limit, limit);
    const glm::vec3 fb = glm::clamp(glm::floor((hi - grid.origin) / grid.voxelSize), -limit, limit);
    const glm::ivec3 a = glm::max(glm::ivec3(fa) - 3, glm::ivec3(0));
    const glm::ivec3 b = glm::min(glm::ivec3(fb) + 2, glm::ivec3(n - 1));
    if (glm::any(glm::greaterThan(a, b))) return false;  // misses the grid
    if (keep.w == 0) return true;
    const glm::ivec3 k = glm::ivec3(keep);
    return !(glm::all(glm::greaterThanEqual(a, k)) && glm::all(glm::lessThan(b, k + n)));
}

ComputeTiling computeTilingFor(VkPhysicalDeviceType type) {
    if (type == VK_PHYSICAL_DEVICE_TYPE_CPU)
        return {sh::VOXC_WALK_COLUMNS_CPU, sh::VOXC_LANE_COLUMNS_CPU, sh::VOXC_PENDING};
    return {sh::VOXC_WALK_COLUMNS_GPU, sh::VOXC_LANE_COLUMNS_GPU, sh::VOXC_PENDING_GPU};
}

void ComputeVoxelizer::setTiling(ComputeTiling tiling) {
    if (tiling.laneColumns == 0 || tiling.laneColumns > sh::VOXC_MAX_LANE_COLUMNS)
        throw std::invalid_argument("voxelizer: a tile invocation walks 1.." +
                                    std::to_string(sh::VOXC_MAX_LANE_COLUMNS) + " columns");
    if (tiling.pending == 0 || tiling.pending > sh::VOXC_PENDING)
        throw std::invalid_argument("voxelizer: a walk collects 1.." + std::to_string(sh::VOXC_PENDING) +
                                    " hits before sampling them");
    tiling_ = tiling;
}

ComputeVoxelizer::ComputeVoxelizer(const gpu::Context& ctx, const gpuscene::SceneGpu& scene)
    : ctx_(ctx), drawCount_(scene.ranges.size()),
      tiling_(computeTilingFor(ctx.properties.deviceType)) {
    if (!ctx.features.float64)
        throw std::runtime_error("voxelizer: compute needs the Vulkan feature shaderFloat64 (its exact triangle/voxel "
                                 "test), which " + ctx.deviceName + " lacks or the application did not enable; "
                                 "use geometry");
    const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
    gpu::LayoutDesc layout;
    layout.bindings = {{sh::BIND_VOXC_GRID, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, cs},
                       {sh::BIND_VOXC_DRAWS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VOXC_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VOXC_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, cs},
                       {sh::BIND_VOXC_INDEX, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VOXC_VERTICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VOXC_INDICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VOXC_GROUPS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VOXC_TILES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VOXC_INDIRECT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VOXC_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs},
                       {sh::BIND_VOXC_EXTENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, cs}};
    layout.extraSet = scene.textureTable->layout();
    layout.pushConstantBytes = sizeof(sh::VoxelizeComputePush);
    layout.pushConstantStages = cs;
    pipeline_ = gpu::Pipeline(ctx, gpu::Spirv(kComp), layout, "voxelize (compute)");

    std::vector<sh::VoxcGroup> groups;
    appendGroups(scene, false, groups);
    staticGroups_ = uint32_t(groups.size());
    staticGroupsHost_ = groups;
    appendGroups(scene, true, groups);
    dynamicGroups_ = uint32_t(groups.size()) - staticGroups_;
    if (groups.empty()) groups.push_back({});  // a buffer needs a size; no dispatch reads it
    groups_ = gpu::createBuffer(ctx, groups.data(), groups.size() * sizeof(sh::VoxcGroup),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "voxelize groups");
    scrollGroups_ = gpu::Buffer(ctx, std::max(staticGroups_, 1u) * sizeof(sh::VoxcGroup),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                gpu::MemoryUse::Device, "voxelize scroll groups");
    tiles_ = gpu::Buffer(ctx, sh::VOXC_MAX_TILES * sizeof(sh::VoxcTile), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                         gpu::MemoryUse::Device, "voxelize tiles");
    indirect_ = gpu::Buffer(ctx, 4 * sizeof(uint32_t),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            gpu::MemoryUse::Device, "voxelize tile dispatch");
}

void ComputeVoxelizer::voxelize(VkCommandBuffer cmd, gpu::Tracker& tracker, const gpuscene::SceneGpu& scene,
                                const VoxelVolumes& v, VoxelizeMode mode) const {
    // The group table was built from this scene's draws.
    if (scene.ranges.size() != drawCount_)
        throw std::logic_error("ComputeVoxelizer::voxelize: the scene's draws changed");
    const bool dynamic = mode == VoxelizeMode::Dynamic;
    uint32_t first = dynamic ? staticGroups_ : 0, count = dynamic ? dynamicGroups_ : staticGroups_;
    // Buffers are not images: their uses are stage + access pairs (as bounce.cpp's statistics).
    const VkPipelineStageFlags2 compute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    const VkAccessFlags2 readWrite = VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    const gpu::Buffer* groupTable = &groups_;
    if (!dynamic && v.keptByScroll.w != 0) {
        // After a clipmap scroll only the exposed slabs are written: every
        // triangle would load itself to find that out, so groups far from the
        // slabs are left out here (their bounds from the scene's host copy).
        std::vector<sh::VoxcGroup> selected;
        for (const sh::VoxcGroup& g : staticGroupsHost_) {
            // The group's draw, and its chunk: its first triangle within the draw over VOXC_GROUP.
            const uint32_t d = g.draw.x, chunk = (g.draw.y - scene.ranges.at(d).firstIndex) / (3 * sh::VOXC_GROUP);
            glm::vec3 lo, hi;
            chunkWorldBounds(scene.primitiveChunks.at(scene.drawPrimitive.at(d)).at(chunk), scene.drawWorld.at(d), lo, hi);
            if (groupReachesWrittenVoxels(lo, hi, v.grid, v.keptByScroll)) selected.push_back(g);
        }
        first = 0;
        count = uint32_t(selected.size());
        // When every group is needed the table as it is serves, without an upload.
        if (count > 0 && count < staticGroups_) {
            tracker.buffer(scrollGroups_, gpu::use::BufferTransferWrite).flush(cmd);
            // vkCmdUpdateBuffer takes at most 65536 bytes a call.
            const size_t perCall = 65536 / sizeof(sh::VoxcGroup);
            for (size_t at = 0; at < selected.size(); at += perCall) {
                const size_t n = std::min(perCall, selected.size() - at);
                vkCmdUpdateBuffer(cmd, scrollGroups_.handle(), at * sizeof(sh::VoxcGroup), n * sizeof(sh::VoxcGroup),
                                  selected.data() + at);
            }
            tracker.buffer(scrollGroups_, compute, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
            groupTable = &scrollGroups_;
        }
    }
    if (count == 0) return;

    tracker.buffer(indirect_, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT).flush(cmd);
    const uint32_t reset[4] = {0, 1, 1, 0};  // no tiles queued: an empty dispatch
    vkCmdUpdateBuffer(cmd, indirect_.handle(), 0, sizeof(reset), reset);

    tracker.image(v.accum, gpu::use::ComputeReadWrite)
        .buffer(v.index, gpu::use::BufferComputeReadWrite)
        .buffer(v.extents, gpu::use::BufferComputeReadWrite)
        .buffer(indirect_, compute, readWrite)
        .buffer(tiles_, compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT)
        .buffer(v.list, gpu::use::BufferComputeReadWrite)
        .flush(cmd);
    gpu::bind(cmd, pipeline_);
    gpu::Descriptors()
        .uniformBuffer(sh::BIND_VOXC_GRID, v.gridBuffer.handle())
        .storageBuffer(sh::BIND_VOXC_DRAWS, scene.draws.handle())
        .storageBuffer(sh::BIND_VOXC_MATERIALS, scene.materials.handle())
        .storageImage(sh::BIND_VOXC_ACCUM, v.accum.view())
        .storageBuffer(sh::BIND_VOXC_INDEX, v.index.handle())
        .storageBuffer(sh::BIND_VOXC_EXTENTS, v.extents.handle())
        .storageBuffer(sh::BIND_VOXC_VERTICES, scene.vertices.handle())
        .storageBuffer(sh::BIND_VOXC_INDICES, scene.indices.handle())
        .storageBuffer(sh::BIND_VOXC_GROUPS, groupTable->handle())
        .storageBuffer(sh::BIND_VOXC_TILES, tiles_.handle())
        .storageBuffer(sh::BIND_VOXC_INDIRECT, indirect_.handle())
        .storageBuffer(sh::BIND_VOXC_LIST, v.list.handle())
        .push(ctx_, cmd, pipeline_);
    VkDescriptorSet textures = scene.textureTable->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.layout(), sh::SET_TEXTURES, 1, &textures,
                            0, nullptr);
    const uint32_t mode32 = dynamic ? sh::VOXELIZE_DYNAMIC : sh::VOXELIZE_STATIC;
    // Past maxComputeWorkGroupCount[0] (65535 at least) the groups wrap into y.
    const uint32_t row = std::min(count, ctx_.properties.limits.maxComputeWorkGroupCount[0]);
    const glm::uvec4 tiling(tiling_.walkColumns, tiling_.laneColumns, tiling_.pending, 0);
    // x row width, y bilinear taps, z textures per material: base colour, and
    // the emissive texture only where a material has one:
    // llvmpipe runs the loop's sample for every triangle even where its
    // material has no such texture.
    const glm::uvec4 dispatch(row, 4, scene.emissiveTextures ? 2u : 1u, 0);
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT,
                       sh::VoxelizeComputePush{glm::uvec4(first, count, mode32, sh::VOXC_PHASE_TRIANGLES),
                                               dispatch, tiling});
    vkCmdDispatch(cmd, row, gpu::groupCount(count, row), 1);

    // The tiles the triangle phase queued; its atomics and the tile phase's
    // commute, but two dispatches writing the volumes still need the barrier.
    tracker.image(v.accum, gpu::use::ComputeReadWrite)
        .buffer(v.index, gpu::use::BufferComputeReadWrite)
        .buffer(indirect_, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | compute,
                VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT)
        .buffer(tiles_, compute, VK_ACCESS_2_SHADER_STORAGE_READ_BIT)
        .buffer(v.list, gpu::use::BufferComputeReadWrite)
        .flush(cmd);
    gpu::pushConstants(cmd, pipeline_, VK_SHADER_STAGE_COMPUTE_BIT,
                       sh::VoxelizeComputePush{glm::uvec4(first, count, mode32, sh::VOXC_PHASE_TILES),
                                               dispatch, tiling});
    vkCmdDispatchIndirect(cmd, indirect_.handle(), 0);
}

}  // namespace dvsgi::vxgi
