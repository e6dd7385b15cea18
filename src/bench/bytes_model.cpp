#include "bench/bytes_model.h"

#include <algorithm>

#include "shared/bounce_pass.h"
#include "shared/voxel_data.h"
#include "vxgi/bounce.h"
#include "vxgi/volumes.h"

namespace dvsgi::bench {

namespace {

namespace sh = dvsgi::shader;

// Formats from docs/ARCHITECTURE.md ("Volumes", "The frame").
constexpr uint64_t kAttributeBytes = sh::VOXEL_CHANNELS * 4;  // 16 R32F channels per slot
constexpr uint64_t kExtentBytes = 4;                          // the extents, uint32 per slot
constexpr uint64_t kIndexBytes = 4;                           // R32_UINT slot index per grid voxel
constexpr uint64_t kVoxelLightBytes = 8;                      // RGBA16F: direct light, radiance, directional
constexpr uint64_t kListEntryBytes = 4;                       // occupied-voxel list: packed coordinate
// The bounce reads the fragment count, albedo and six normal weights, not the
// emission (the direct light already holds it).
constexpr uint64_t kBounceAttributeBytes = 10 * 4;
constexpr uint64_t kGBufferColorBytes = 8;  // base, normal, emission: RGBA16F each
constexpr uint64_t kDepthBytes = 4;         // D32
constexpr uint64_t kShadowGradientBytes = 4;  // RG16F, beside each shadow-map texel
constexpr uint64_t kDirectBytes = 16;       // RGBA32F direct radiance
constexpr uint64_t kVisibilityBytes = 2;    // R16F light visibility
constexpr uint64_t kTermBytes = 8;          // RGBA16F indirect diffuse, specular
constexpr uint64_t kOutputBytes = 16;       // RGBA32F
constexpr uint64_t kHistoryBytes = 16 + 8;  // temporal history: RGBA32F sum, RGBA16F normal + depth
constexpr uint64_t kRayResultBytes = sh::BOUNCE_RAYS_SLOT_BYTES;  // the bounce's rays' light per slot
// The rays' normals: the fragment count and six normal weights in, one packed word per slot out.
constexpr uint64_t kRayNormalAttributeBytes = 7 * 4;
constexpr uint64_t kRayNormalBytes = sh::BOUNCE_RAY_NORMAL_SLOT_BYTES;
constexpr uint64_t kNormalWeightBytes = 6 * 4;  // the six normal weights alone (the filter's seenFront)

uint64_t cube(uint64_t s) { return s * s * s; }

// Anisotropic filtering of all levels: level 0 runs over the occupied-voxel
// list and reads those voxels' radiance once (the six directions share the
// reads; the empty voxels beside them in their cells are not counted), level
// l > 0 reads level l - 1 of each of the six volumes; every level of the six
// is written (level 0 by its clear and the occupied cells' composites, counted once).
// With `backsDark` level 0 also reads each listed voxel's index word and its
// six normal weights.
PassTraffic filtering(uint32_t n, uint64_t occupied, bool backsDark, const char* name) {
    PassTraffic p{name};
    const uint32_t levels = vxgi::directionalMipCount(n);
    p.readBytes = occupied * (kListEntryBytes + kVoxelLightBytes +
                              (backsDark ? kIndexBytes + kNormalWeightBytes : 0));
    for (uint32_t l = 0; l < levels; ++l) {
        const uint64_t target = cube(std::max(uint64_t(n / 2) >> l, uint64_t(1)));
        p.writtenBytes += 6 * target * kVoxelLightBytes;
        if (l + 1 < levels) p.readBytes += 6 * target * kVoxelLightBytes;
    }
    return p;
}

}  // namespace

std::vector<PassTraffic> passTraffic(const ModelInputs& in) {
    std::vector<PassTraffic> out;
    const uint64_t n3 = cube(in.voxels);
    const uint64_t occupied = in.occupiedVoxels, dynamic = std::min(in.dynamicVoxels, occupied);
    const uint64_t staticVoxels = occupied - dynamic;
    const uint64_t geometry = in.staticGeometryBytes + in.dynamicGeometryBytes;
    const uint64_t internal = uint64_t(in.internalWidth) * in.internalHeight;
    const uint64_t trace = uint64_t(in.traceWidth) * in.traceHeight;
    const uint64_t output = uint64_t(in.outputWidth) * in.outputHeight;
    const uint64_t bounces = in.bounces;

    if (in.voxels > 0) {
        // The whole-grid clear (the renderer's before 2026-11-28, modelled for
        // older JSONs): every index and radiance texel and every slot's
        // attributes and direct light are written.
        const uint64_t slots = in.slots ? in.slots : vxgi::defaultSlotCapacity(in.voxels);
        out.push_back({"clear all voxels", 0,
                       n3 * (kIndexBytes + kVoxelLightBytes) +
                           slots * (kAttributeBytes + kExtentBytes + kVoxelLightBytes)});
        // A static voxelization clears only what the list holds (all of last
        // frame's voxels, static and dynamic), as the dynamic clear does.
        out.push_back({"clear occupied voxels", occupied * kListEntryBytes,
                       occupied * (kAttributeBytes + kExtentBytes + 2 * kVoxelLightBytes + kIndexBytes)});
        out.push_back({"voxelize static", in.staticGeometryBytes,
                       staticVoxels * (kAttributeBytes + kExtentBytes + kIndexBytes + kListEntryBytes)});
        // The voxels dynamic geometry wrote last frame (their list entries);
        // this frame's count stands in for them (the object moves a voxel or
        // less per frame). Slots (attributes, extents, direct light), radiance and index are zeroed.
        out.push_back({"clear dynamic voxels", dynamic * kListEntryBytes,
                       dynamic * (kAttributeBytes + kExtentBytes + 2 * kVoxelLightBytes + kIndexBytes)});
        out.push_back({"voxelize dynamic", in.dynamicGeometryBytes + dynamic * kIndexBytes,
                       dynamic * (kAttributeBytes + kExtentBytes + kIndexBytes + kListEntryBytes)});
    }
    // Every view rasterizes all geometry and writes its whole layer: depth and the casters' gradients.
    out.push_back({"shadow maps", geometry * in.shadowViews,
                   uint64_t(in.shadowMapSize) * in.shadowMapSize * (kDepthBytes + kShadowGradientBytes) * in.shadowViews});
    if (in.voxels > 0) {
        // Direct light into the slot and the radiance volume; the extents
        // place a floor's or a wall's shadow lookup on its surface.
        out.push_back({"voxel direct light", occupied * (kListEntryBytes + kAttributeBytes + kExtentBytes),
                       occupied * 2 * kVoxelLightBytes});
        // Rays read no filtered light: with a ray bounce after it, the voxel
        // light is not filtered until that bounce has run.
        if (!(in.bounceRays && bounces > 0)) out.push_back(filtering(in.voxels, occupied, in.backsDark, "voxel filtering"));
        // Cone and ray samples are not counted: the bytes are those of the
        // voxel's own attributes, direct light and result (with rays, also
        // the list and attributes read again by the shading dispatch, the
        // per-slot result the rays hand over, and the dispatch before the
        // rays that packs each voxel's normal and sets its cells' occupancy
        // bits, one word per level read and written, after the bits' clear).
        PassTraffic bounce{"voxel bounce",
                           bounces * occupied * (kListEntryBytes + kBounceAttributeBytes + kVoxelLightBytes),
                           bounces * occupied * kVoxelLightBytes};
        if (in.bounceRays) {
            bounce.readBytes += bounces * occupied *
                                (2 * kListEntryBytes + kBounceAttributeBytes + kRayResultBytes + kRayNormalAttributeBytes);
            const uint64_t bitWords = occupied * sh::RAY_OCCUPANCY_LEVELS * sizeof(uint32_t);
            bounce.readBytes += bounces * bitWords;
            bounce.writtenBytes += bounces * (occupied * (kRayResultBytes + kRayNormalBytes) + bitWords +
                                              vxgi::rayOccupancyBytes(in.voxels));
        }
        out.push_back(bounce);
        PassTraffic again = filtering(in.voxels, occupied, in.backsDark, "voxel filtering (bounce)");
        again.readBytes *= bounces;
        again.writtenBytes *= bounces;
        out.push_back(again);
    }
    out.push_back({"gbuffer", geometry, internal * (3 * kGBufferColorBytes + kDepthBytes)});
    out.push_back({"direct lighting", internal * (3 * kGBufferColorBytes + kDepthBytes),
                   internal * (kDirectBytes + kVisibilityBytes)});
    if (in.voxels > 0) {
        // Base colour (roughness, metallic), normal and depth per traced pixel.
        out.push_back({"cone tracing", trace * (2 * kGBufferColorBytes + kDepthBytes), trace * 2 * kTermBytes});
        // Per pass, the term, normal and depth of each trace pixel (read once;
        // the 3x3 neighbours share them), the resolved term written.
        if (in.resolvePasses > 0)
            out.push_back({"cone set resolve", in.resolvePasses * trace * (kTermBytes + kGBufferColorBytes + kDepthBytes),
                           in.resolvePasses * trace * kTermBytes});
        if (trace != internal)
            out.push_back({"upsample", trace * 2 * kTermBytes + internal * (kGBufferColorBytes + kDepthBytes),
                           internal * 2 * kTermBytes});
    }
    if (in.voxels > 0 && in.temporal)
        // Depth, normal, the indirect term and last frame's history in; the
        // blended term and this frame's history out.
        out.push_back({"temporal indirect", internal * (kDepthBytes + kGBufferColorBytes + kTermBytes + kHistoryBytes),
                       internal * (kTermBytes + kHistoryBytes)});
    const uint64_t terms = in.voxels > 0 ? 2 * kTermBytes : 0;
    out.push_back({"composite", internal * (kDirectBytes + terms), output * kOutputBytes});
    return out;
}

const PassTraffic* findPass(const std::vector<PassTraffic>& passes, const std::string& name) {
    for (const PassTraffic& p : passes)
        if (p.name == name) return &p;
    return nullptr;
}

double gigabytesPerSecond(uint64_t bytes, double ms) { return ms > 0.0 ? double(bytes) / (ms * 1e6) : 0.0; }

}  // namespace dvsgi::bench
