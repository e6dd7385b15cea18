#include "gpuscene/draw_list.h"

#include <algorithm>
#include <cmath>

#include "gpuscene/scene_gpu.h"
#include "shared/geometry_pass.h"

namespace dvsgi::gpuscene {

namespace {

namespace sh = dvsgi::shader;

bool picked(const DrawRange& r, DrawFilter filter) {
    return filter == DrawFilter::All || (filter == DrawFilter::Static) == !r.dynamic;
}

// Whether the box's eight clip-space corners all lie outside one plane of the
// clip volume. The planes are linear in homogeneous coordinates, so then the
// whole box, and every triangle in it, does too, corners behind the eye
// included. The margin, 1e-4 of w, absorbs the rounding between this
// product and the vertex shader's (view-projection times model times
// position): a triangle it could misjudge lies within 1e-4 of the view's
// half-width of a clip plane, far inside any pixel at the image sizes used.
bool outsideClipVolume(const glm::vec4 (&c)[8]) {
    uint32_t all = 0x3f;
    for (const glm::vec4& p : c) {
        const float m = 1e-4f * std::abs(p.w) + 1e-6f;
        const uint32_t out = (p.x < -p.w - m ? 1u : 0u) | (p.x > p.w + m ? 2u : 0u) | (p.y < -p.w - m ? 4u : 0u) |
                             (p.y > p.w + m ? 8u : 0u) | (p.z < -m ? 16u : 0u) | (p.z > p.w + m ? 32u : 0u);
        all &= out;
        if (all == 0) return false;
    }
    return true;
}

}  // namespace

uint64_t DrawList::triangles() const {
    uint64_t n = 0;
    for (const std::vector<DrawRun>* runs : {&opaque, &alphaTested})
        for (const DrawRun& r : *runs) n += r.indexCount / 3;
    return n;
}

DrawList visibleDraws(const SceneGpu& scene, const glm::mat4& viewProj, DrawFilter filter) {
    DrawList list;
    const uint32_t chunkIndices = 3 * SceneGpu::kBoundsChunk;
    for (uint32_t d = 0; d < scene.ranges.size(); ++d) {
        const DrawRange& r = scene.ranges[d];
        if (!picked(r, filter)) continue;
        std::vector<DrawRun>& runs = r.alphaTested ? list.alphaTested : list.opaque;
        const glm::mat4 toClip = viewProj * scene.drawWorld[d];
        const std::vector<scene::Bounds>& chunks = scene.primitiveChunks[scene.drawPrimitive[d]];
        uint32_t runChunks = 0;  // chunks in runs.back() if this draw's last chunk was kept, else 0
        for (uint32_t c = 0; c < chunks.size(); ++c) {
            const scene::Bounds& b = chunks[c];
            glm::vec4 clip[8];
            for (int k = 0; k < 8; ++k) clip[k] = toClip * glm::vec4(b.corner(k), 1.0f);
            if (outsideClipVolume(clip)) {
                runChunks = 0;
                continue;
            }
            const uint32_t first = r.firstIndex + c * chunkIndices;
            const uint32_t count = std::min(chunkIndices, r.firstIndex + r.indexCount - first);
            if (runChunks > 0 && runChunks < kRunChunks) {
                runs.back().indexCount += count;
                ++runChunks;
            } else {
                runs.push_back({d, first, count, r.vertexOffset, r.baseColorOnly});
                runChunks = 1;
            }
        }
    }
    return list;
}

void recordDraws(VkCommandBuffer cmd, const DrawList& list, const DrawPipelines& pipelines, uint32_t view) {
    const gpu::Pipeline* bound = nullptr;
    for (bool alpha : {false, true}) {
        const gpu::Pipeline& full = alpha ? pipelines.alphaTested : pipelines.opaque;
        const gpu::Pipeline* plain = alpha ? pipelines.alphaTestedBaseColorOnly : pipelines.opaqueBaseColorOnly;
        for (const DrawRun& r : alpha ? list.alphaTested : list.opaque) {
            const gpu::Pipeline* p = r.baseColorOnly && plain ? plain : &full;
            if (p != bound) gpu::bind(cmd, *p);
            bound = p;
            const sh::DrawPush push{glm::uvec4(r.draw, view, 0, 0)};
            gpu::pushConstants(cmd, *p, VK_SHADER_STAGE_VERTEX_BIT, push);
            vkCmdDrawIndexed(cmd, r.indexCount, 1, r.firstIndex, r.vertexOffset, 0);
        }
    }
}

}  // namespace dvsgi::gpuscene
