#include "device_faults.h"

#include <cstdio>
#include <string_view>

#include "vxgi/volumes.h"

namespace dvsgi::app {

namespace {

bool has(std::string_view s, std::string_view part) { return s.find(part) != std::string_view::npos; }

// The option (with its value) that decided the size of `resource`, and for the
// voxel grid the total its volumes need. Empty when no option sized it.
struct Culprit {
    std::string setting;
    std::string total;  // "; the voxel volumes need 1.2 GiB in all"
    std::string advice;
};

Culprit culprit(std::string_view resource, const RenderOptions& o) {
    Culprit c;
    if (has(resource, "voxel") || has(resource, "directional volume") || has(resource, "bounce stat")) {
        c.setting = "--voxels " + std::to_string(o.settings.voxels);
        uint64_t total = 0;
        const uint32_t n = o.settings.voxels;
        const bool rays = render::bounceTracesRays(o.settings), gatherRays = render::gatherTracesRays(o.settings);
        for (const vxgi::VolumeMemory& m : vxgi::volumeMemory(n, vxgi::defaultSlotCapacity(n), rays, gatherRays))
            total += m.bytes;
        c.total = "; the voxel volumes need " + formatBytes(double(total)) + " in all";
        c.advice = "fewer --voxels";
    } else if (has(resource, "shadow map")) {
        c.setting = "--shadow-map " + std::to_string(o.settings.shadowMapSize);
        c.advice = "a smaller --shadow-map";
    } else if (has(resource, "gbuffer") || has(resource, "direct radiance") || has(resource, "light visibility") ||
               has(resource, "indirect diffuse") || has(resource, "specular") || resource == "output") {
        c.setting = "--width " + std::to_string(o.settings.width) + " --height " + std::to_string(o.settings.height);
        if (o.settings.supersample > 1) c.setting += " --supersample " + std::to_string(o.settings.supersample);
        c.advice = "a smaller image";
    } else if (has(resource, "texture")) {
        c.setting = o.scene.empty() ? "the built-in scene" : o.scene;
        c.advice = "smaller textures";
    } else if (resource == "vertices" || resource == "indices" || resource == "draws" || resource == "materials") {
        c.setting = o.scene.empty() ? "the built-in scene" : o.scene;
        c.advice = "a smaller scene";
    }
    return c;
}

}  // namespace

std::string formatBytes(double bytes) {
    char buf[32];
    if (bytes >= 1024.0 * 1024.0 * 1024.0)
        std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
    else if (bytes >= 1024.0 * 1024.0)
        std::snprintf(buf, sizeof buf, "%.1f MiB", bytes / (1024.0 * 1024.0));
    else
        std::snprintf(buf, sizeof buf, "%.0f KiB", bytes / 1024.0);
    return buf;
}

std::string describeGpuError(const gpu::GpuError& error, const RenderOptions& o) {
    const auto* m = dynamic_cast<const gpu::DeviceMemoryError*>(&error);
    if (!m) return error.what();
    const Culprit c = culprit(m->resource, o);
    std::string line = c.setting.empty() ? std::string() : c.setting + ": ";
    line += (m->bytes > 0 ? "allocating the " : "creating the ") + m->resource;
    if (m->bytes > 0) line += " (" + formatBytes(double(m->bytes)) + c.total + ")";
    else if (!c.total.empty()) line += " (" + c.total.substr(2) + ")";
    line += " failed: ";
    if (m->bytes > 0 && m->heapBytes > 0 && m->bytes > m->heapBytes)
        line += "more than " + m->device + "'s " + formatBytes(double(m->heapBytes)) + " memory heap holds";
    else if (m->bytes > 0 && m->maxAllocation > 0 && m->bytes > m->maxAllocation)
        line += "more than " + m->device + " allows in one allocation (" + formatBytes(double(m->maxAllocation)) + ")";
    else
        line += m->device + " has no room left in its " + formatBytes(double(m->heapBytes)) + " memory heap";
    line += " (" + std::string(gpu::resultName(m->result)) + ")";
    if (!c.advice.empty()) line += "; try " + c.advice;
    return line;
}

}  // namespace dvsgi::app
