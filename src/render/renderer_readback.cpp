// What the Renderer hands back after a frame: the output and its terms, the
// G-buffer averaged to output size, and the GPU memory it holds. Kept apart
// from renderer.cpp, which records the frame.
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <glm/gtc/packing.hpp>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpuscene/scene_gpu.h"
#include "render/renderer.h"
#include "render/shadows.h"
#include "vxgi/bounce.h"
#include "vxgi/voxelize.h"

namespace dvsgi::render {

const gpu::Image& Renderer::outputImage() const { return targets_->output; }

image::ImageRGBA32F Renderer::readOutput() const {
    const std::vector<uint8_t> bytes = gpu::readbackImage(ctx_, targets_->output, gpu::use::ComputeWrite);
    image::ImageRGBA32F img;
    img.width = settings_.width;
    img.height = settings_.height;
    img.rgba.resize(size_t(img.width) * img.height * 4);
    std::memcpy(img.rgba.data(), bytes.data(), img.rgba.size() * sizeof(float));
    return img;
}

std::vector<MemoryItem> Renderer::memory() const {
    uint64_t textures = 0;
    for (const gpu::Image& t : sceneGpu_->textures) textures += t.memorySize();
    std::vector<MemoryItem> items = {
        {"geometry buffers", sceneGpu_->vertices.size() + sceneGpu_->indices.size() + sceneGpu_->draws.size()},
        {"textures", textures},
        {"shadow maps", targets_->shadowMap.memorySize() + targets_->shadowGradient.memorySize()},
        {"g-buffer", targets_->gbuffer.memoryBytes()},
        {"direct radiance", targets_->direct.memorySize() + targets_->visibility.memorySize()},
        {"cone-traced terms", targets_->diffuse.memorySize() + targets_->specular.memorySize() +
                                  targets_->turnedDiffuse.memorySize() +
                                  (targets_->reducedTrace() ? targets_->traceDiffuse.memorySize() +
                                                                  targets_->traceSpecular.memorySize()
                                                            : 0)},
        {"output", targets_->output.memorySize()},
    };
    if (shadows_->cacheBytes()) items.push_back({"shadow maps: kept static depth and gradients", shadows_->cacheBytes()});
    if (targets_->temporal.memoryBytes()) items.push_back({"indirect history", targets_->temporal.memoryBytes()});
    if (voxelizer_) {
        items.push_back({"voxel slot index", volumes_->index.size()});
        items.push_back({"voxel attributes", volumes_->accum.memorySize()});
        items.push_back({"voxel radiance", volumes_->radiance.memorySize()});
        items.push_back({"voxel direct light", volumes_->direct.memorySize()});
        items.push_back({"voxel side light", volumes_->sides.memorySize()});
        if (bounce_->rayBytes()) items.push_back({"voxel bounce rays' light", bounce_->rayBytes()});
        if (rayData_->bytes()) items.push_back({"voxel rays' normals and occupancy", rayData_->bytes()});
        items.push_back({"directional volumes", volumes_->directional.memorySize()});
        items.push_back({"occupied-voxel list", volumes_->list.size()});
        // --clipmap: the items above are level 0's; each coarser level holds
        // its index, attributes, direct and side light and list, and one set of dense
        // volumes serves them all.
        const std::vector<const vxgi::VoxelVolumes*> levels = levelVolumes();
        for (size_t l = 1; l < levels.size(); ++l)
            items.push_back({"clipmap level " + std::to_string(l) + " voxels", levels[l]->ownBytes()});
        if (const std::shared_ptr<vxgi::DenseVolumes> scratch = clipScratch(); scratch && levels.size() > 2)
            items.push_back({"clipmap levels 1-" + std::to_string(levels.size() - 1) +
                                 " radiance and directional (shared)",
                             scratch->bytes()});
        if (atlases_) items.push_back({"clipmap atlases (radiance, directional)", atlases_->bytes()});
        uint64_t history = 0;
        for (const gpu::Image& img : voxelHistory_) history += img.memorySize();
        if (history) items.push_back({"voxel radiance history (--voxel-temporal-alpha)", history});
        if (pv_) items.push_back({"pv last frame's attributes and list", pv_->memoryBytes()});
        uint64_t rsm = 0, around = 0;
        for (const PvView& v : rsm_) rsm += v.gbuffer.memoryBytes();
        for (const PvView& v : around_) around += v.gbuffer.memoryBytes();
        if (rsm) items.push_back({"pv reflective shadow maps", rsm});
        if (around) items.push_back({"pv views around the camera", around});
    }
    return items;
}

image::ImageRGBA32F Renderer::readTerm(uint32_t term) const {
    if (settings_.view.mode != ViewMode::Final)
        throw std::runtime_error("view: terms exist only for the final image, not the voxel views");
    auto composite = [&](uint32_t t) {
        ctx_.submitAndWait([&](VkCommandBuffer cmd) { recordComposite(cmd, t, nullptr); });
    };
    composite(term);
    image::ImageRGBA32F img = readOutput();
    composite(settings_.outputTerm);
    return img;
}

namespace {

// Internal-size samples (4 channels per texel) to output size: the per-pixel
// average of the k x k block, the same footprint the composite averages.
image::ImageRGBA32F boxAverage(const std::vector<float>& samples, uint32_t width, uint32_t height, uint32_t k) {
    image::ImageRGBA32F out = image::ImageRGBA32F::blank(width, height);
    const uint32_t iw = width * k;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            float* o = out.at(x, y);
            for (int c = 0; c < 4; ++c) o[c] = 0.0f;
            for (uint32_t j = 0; j < k; ++j)
                for (uint32_t i = 0; i < k; ++i) {
                    const float* s = samples.data() + (size_t(y * k + j) * iw + x * k + i) * 4;
                    for (int c = 0; c < 4; ++c) o[c] += s[c];
                }
            for (int c = 0; c < 4; ++c) o[c] /= float(k * k);
        }
    return out;
}

std::vector<float> halfTexels(const std::vector<uint8_t>& bytes) {
    std::vector<float> out(bytes.size() / 2);
    for (size_t i = 0; i < out.size(); ++i) {
        uint16_t h;
        std::memcpy(&h, bytes.data() + 2 * i, 2);
        out[i] = glm::unpackHalf1x16(h);
    }
    return out;
}

}  // namespace

Renderer::SurfaceImages Renderer::readSurface() const {
    if (settings_.view.mode != ViewMode::Final)
        throw std::runtime_error("view: the G-buffer exists only for the final image, not the voxel views");
    const uint32_t k = settings_.supersample, w = settings_.width, h = settings_.height;
    const uint32_t iw = w * k, ih = h * k;
    SurfaceImages out;
    out.albedo = boxAverage(halfTexels(gpu::readbackImage(ctx_, targets_->gbuffer.base, gpu::use::ShaderRead)), w, h, k);
    out.normal = boxAverage(halfTexels(gpu::readbackImage(ctx_, targets_->gbuffer.normal, gpu::use::ShaderRead)), w, h, k);
    for (size_t p = 0; p < out.normal.pixelCount(); ++p) {
        float* n = out.normal.rgba.data() + 4 * p;
        const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 0.0f)
            for (int c = 0; c < 3; ++c) n[c] /= len;
    }

    // Depth: D32 holds post-projection depth; undo the projection per sample
    // so the layer is metres along the view axis, which averages meaningfully.
    const std::vector<uint8_t> bytes = gpu::readbackImage(ctx_, targets_->gbuffer.depth, gpu::use::DepthRead);
    const glm::mat4 invProj = glm::inverse(projectionMatrix(camera_, iw, ih));
    out.depth = image::ImageRGBA32F::blank(w, h);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            double sum = 0.0;
            uint32_t hits = 0;
            for (uint32_t j = 0; j < k; ++j)
                for (uint32_t i = 0; i < k; ++i) {
                    const uint32_t sx = x * k + i, sy = y * k + j;
                    float d;
                    std::memcpy(&d, bytes.data() + (size_t(sy) * iw + sx) * 4, 4);
                    if (d >= 1.0f) continue;  // cleared: no geometry
                    const glm::vec4 ndc((2.0f * (float(sx) + 0.5f)) / float(iw) - 1.0f,
                                        (2.0f * (float(sy) + 0.5f)) / float(ih) - 1.0f, d, 1.0f);
                    const glm::vec4 v = invProj * ndc;
                    sum += double(-v.z / v.w);
                    ++hits;
                }
            float* o = out.depth.at(x, y);
            const float z = hits ? float(sum / hits) : std::numeric_limits<float>::infinity();
            o[0] = o[1] = o[2] = z;
            o[3] = float(hits) / float(k * k);
        }
    return out;
}

}  // namespace dvsgi::render
