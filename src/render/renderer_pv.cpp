// The Renderer's progressive voxelization (--voxelizer pv, docs/pv.md): the
// depth views its cleanup reads, the extra G-buffers (reflective shadow maps,
// views around the camera) and the frame's voxel passes in this mode.
#include "render/renderer.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpuscene/draw_list.h"
#include "render/gbuffer.h"
#include "render/shadows.h"
#include "shared/pv_pass.h"
#include "shared/scene_data.h"
#include "vxgi/voxel_list.h"

namespace dvsgi::render {

namespace sh = dvsgi::shader;

void Renderer::uploadPvViews() {
    // Four texels of tolerance were set for shadow maps drawn with a
    // slope-scaled bias (1.5 texels of depth slope), which put a lit surface
    // behind where it is, and kept the voxels holding such surfaces up to
    // grazing angles of about 70 degrees. The maps hold exact depths since
    // they keep their casters' planes (shared/shadow_pass.h); the tolerance
    // stays, conservative, as pv's coverage was measured with it.
    constexpr float kShadowTexels = 4.0f;
    std::vector<sh::PvDepthView> views;
    const glm::mat4 camera = viewProjection();
    views.push_back({camera, glm::inverse(camera), glm::vec4(sh::PV_CAMERA_LAYER, 0.0f, 0.0f, 0.0f)});
    for (size_t i = 0; i < shadowViews_.size(); ++i) {
        const glm::vec4& p = shadowViews_[i].params;
        const bool perspective = p.y > 0.5f;
        views.push_back({shadowViews_[i].viewProj, glm::inverse(shadowViews_[i].viewProj),
                         glm::vec4(float(i), perspective ? 0.0f : kShadowTexels * p.x,
                                   perspective ? kShadowTexels * p.x : 0.0f, 0.0f)});
    }
    const VkDeviceSize bytes = views.size() * sizeof(sh::PvDepthView);
    if (!pvViews_ || pvViews_->size() != bytes)
        pvViews_ = std::make_unique<gpu::Buffer>(ctx_, bytes,
                                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                 gpu::MemoryUse::Device, "pv depth views");
    gpu::uploadBuffer(ctx_, *pvViews_, views.data(), bytes);
    pvViewCount_ = uint32_t(views.size());

    // The extra G-buffers: only the matrices and the size matter to the
    // G-buffer pass and the injection. Shadow views keep glm's clip space; the
    // camera's flips y (so row 0 is the top of the image), and the G-buffer's
    // facing test, which turns normals toward the viewer, follows the
    // winding: flip the lights' views too.
    const glm::mat4 flipY = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, -1.0f, 1.0f));
    std::vector<glm::mat4> lights;
    if (settings_.pv.rsm)
        for (const sh::GpuShadowView& v : shadowViews_) lights.push_back(flipY * v.viewProj);
    setPvViews(rsm_, lights, settings_.pv.rsm);
    // Six 90-degree views around the camera, to find what it does not face.
    std::vector<glm::mat4> around;
    if (settings_.pv.views) {
        const glm::vec3 eye(camera_.world[3]);
        const glm::vec3 faces[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        glm::mat4 proj = glm::perspective(glm::half_pi<float>(), 1.0f, camera_.camera.znear, camera_.camera.zfar);
        proj[1][1] *= -1.0f;
        for (const glm::vec3& d : faces)
            around.push_back(proj * glm::lookAt(eye, eye + d, std::abs(d.y) > 0.5f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0)));
    }
    setPvViews(around_, around, settings_.pv.views);
}

void Renderer::setPvViews(std::vector<PvView>& views, const std::vector<glm::mat4>& viewProj, uint32_t size) {
    if (views.size() != viewProj.size()) {
        views.clear();
        for (size_t i = 0; i < viewProj.size(); ++i)
            views.push_back({createGBuffer(ctx_, size, size, true),
                             std::make_unique<gpu::Buffer>(
                                 ctx_, sizeof(sh::FrameConstants),
                                 VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 gpu::MemoryUse::Device, "pv view frame constants")});
    }
    for (size_t i = 0; i < viewProj.size(); ++i) {
        sh::FrameConstants f{};
        f.viewProj = viewProj[i];
        views[i].viewProj = f.viewProj;
        f.invViewProj = glm::inverse(f.viewProj);
        f.sizes = glm::uvec4(size, size, 0u, 0u);
        gpu::uploadBuffer(ctx_, *views[i].frame, &f, sizeof(f));
    }
}

void Renderer::recordPvViews(VkCommandBuffer cmd, const std::vector<PvView>& views, const char* timer) {
    if (views.empty()) return;
    gpu::GpuTimerScope scope(timers_.get(), cmd, timer);
    for (const PvView& v : views) {
        const gpuscene::DrawList draws = gpuscene::visibleDraws(*sceneGpu_, v.viewProj, gpuscene::DrawFilter::All);
        gbuffer_->record(cmd, tracker_, *sceneGpu_, draws, *v.frame, v.gbuffer, nullptr);
    }
}

void Renderer::injectPvViews(VkCommandBuffer cmd, const std::vector<PvView>& views, const char* timer) {
    if (views.empty()) return;
    gpu::GpuTimerScope scope(timers_.get(), cmd, timer);
    vxgi::PvSettings everyTexel = settings_.pv;
    everyTexel.grid = 0;
    for (const PvView& v : views) {
        const GBuffer& g = v.gbuffer;
        const vxgi::PvGBufferInputs in{g.depth, g.base, g.normal, g.emission, *v.frame, samplers_->point.handle()};
        pv_->inject(cmd, tracker_, *volumes_, in, everyTexel, nullptr);
    }
}

// Progressive voxelization needs the frame's depth buffers first: shadow
// maps and G-buffer do not depend on the voxels, so they move ahead of them.
void Renderer::recordProgressiveVoxels(VkCommandBuffer cmd) {
    gpu::GpuTimers* t = timers_.get();
    FrameTargets& f = *targets_;
    recordShadows(cmd);
    recordCameraGBuffer(cmd);
    recordPvViews(cmd, rsm_, "pv rsm");
    recordPvViews(cmd, around_, "pv views");
    const vxgi::PvDepthInputs depth{f.gbuffer.depth, f.shadowMap, *pvViews_, pvViewCount_, samplers_->point.handle()};
    pv_->cleanup(cmd, tracker_, *volumes_, depth, t);
    list_->finish(cmd, tracker_, *volumes_, true);  // the survivors count as "kept" (static)
    const vxgi::PvGBufferInputs g{f.gbuffer.depth, f.gbuffer.base,   f.gbuffer.normal,
                                  f.gbuffer.emission, *frame_, samplers_->point.handle()};
    pv_->inject(cmd, tracker_, *volumes_, g, settings_.pv, t);
    injectPvViews(cmd, rsm_, "pv inject rsm");
    injectPvViews(cmd, around_, "pv inject views");
    list_->finish(cmd, tracker_, *volumes_, false);  // this frame's new voxels come after them
    list_->copyHeader(cmd, tracker_, *volumes_, *listHeader_);
}

}  // namespace dvsgi::render
