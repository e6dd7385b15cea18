#include "view_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include "gpu/check.h"
#include "gpu/context.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "settings_table.h"
#include "view_panel_settings.h"
#include "view_swapchain.h"
#include "vxgi/volumes.h"

namespace dvsgi::app {

namespace {

void checkVk(VkResult r) {
    if (r != VK_SUCCESS) gpu::throwVkError("ImGui Vulkan backend", r);
}

// A combo over fixed string values; true when the choice changed.
bool comboString(const char* label, std::string& value, std::initializer_list<const char*> choices) {
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (const char* c : choices) {
            const bool selected = value == c;
            if (ImGui::Selectable(c, selected) && !selected) {
                value = c;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

// Direction of a node's -Z as yaw/pitch in degrees (yaw 0 = -Z, about +Y).
glm::vec2 yawPitch(const glm::quat& q) {
    const glm::vec3 f = glm::normalize(q * glm::vec3(0, 0, -1));
    return glm::degrees(glm::vec2(std::atan2(f.x, -f.z), std::asin(std::clamp(f.y, -1.0f, 1.0f))));
}

glm::quat fromYawPitch(glm::vec2 deg) {
    const glm::vec2 r = glm::radians(deg);
    return glm::angleAxis(-r.x, glm::vec3(0, 1, 0)) * glm::angleAxis(r.y, glm::vec3(1, 0, 0));
}

}  // namespace

ViewPanel::ViewPanel(const gpu::Context& ctx, GLFWwindow* window, const Swapchain& swapchain) : ctx_(ctx) {
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16};
    VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pi.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pi.maxSets = 16;
    pi.poolSizeCount = 1;
    pi.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(ctx.device, &pi, nullptr, &pool_));

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForVulkan(window, true);
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = ctx.instance;
    info.PhysicalDevice = ctx.physical;
    info.Device = ctx.device;
    info.QueueFamily = ctx.queueFamily;
    info.Queue = ctx.queue;
    info.DescriptorPool = pool_;
    info.MinImageCount = std::max(swapchain.minImageCount(), 2u);
    info.ImageCount = std::max(swapchain.imageCount(), info.MinImageCount);
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkVk;
    ImGui_ImplVulkan_Init(&info, swapchain.renderPass());
    ctx.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ViewPanel::~ViewPanel() {
    vkDeviceWaitIdle(ctx_.device);
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroyDescriptorPool(ctx_.device, pool_, nullptr);
}

bool ViewPanel::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ViewPanel::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

ViewPanel::Actions ViewPanel::build(RenderOptions& o, render::Renderer& renderer, const render::FrameStats& stats,
                                    double frameMs, float& flySpeed, const char* presentMode) {
    Actions a;
    frameMs_.push_back(float(frameMs));
    gpuMs_.push_back(float(stats.gpuMs));
    if (frameMs_.size() > 240) frameMs_.erase(frameMs_.begin());
    if (gpuMs_.size() > 240) gpuMs_.erase(gpuMs_.begin());

    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(380, 560), ImGuiCond_FirstUseEver);
    // Small windows start with the panel collapsed (click its title to open it).
    ImGui::SetNextWindowCollapsed(ImGui::GetIO().DisplaySize.x < 480.0f, ImGuiCond_FirstUseEver);
    ImGui::Begin("dvsgi");
    if (!error_.empty()) {
        // A change that failed (out of memory, say) stays visible until dismissed.
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s", error_.c_str());
        ImGui::PopStyleColor();
        if (ImGui::SmallButton("dismiss")) error_.clear();
    }
    ImGui::Text("%.1f ms/frame, GPU %.1f ms, %s", frameMs, stats.gpuMs, presentMode);
    if (ImGui::Button("Screenshot (EXR + PNG)")) a.screenshot = true;

    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
        scene::Scene& s = renderer.scene();
        const size_t cameras = scene::placedCameras(s, scene::worldMatrices(s)).size();
        int cam = o.settings.camera;
        if (ImGui::SliderInt("camera", &cam, 0, int(std::max<size_t>(cameras, 1) - 1)) && cam != o.settings.camera)
            a.camera = cam;
        bool vsync = o.vsync;
        if (ImGui::Checkbox("vsync", &vsync)) {
            o.vsync = vsync;
            a.recreateSwapchain = true;
        }
        ImGui::SliderFloat("fly speed (m/s)", &flySpeed, 0.01f, 100.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    }
    a.settingsChanged = settingsWidgets(o, renderer);

    scene::Scene& s = renderer.scene();
    if (ImGui::CollapsingHeader("Lights")) {
        for (size_t i = 0; i < s.nodes.size(); ++i) {
            scene::Node& n = s.nodes[i];
            if (n.light < 0 || size_t(n.light) >= s.lights.size()) continue;
            scene::Light& l = s.lights[size_t(n.light)];
            ImGui::PushID(int(i));
            if (ImGui::TreeNode("light", "%s", l.name.empty() ? n.name.c_str() : l.name.c_str())) {
                a.sceneEdited |= ImGui::ColorEdit3("colour", &l.color.x);
                a.sceneEdited |= ImGui::DragFloat("intensity", &l.intensity, 0.05f, 0.0f, 1e6f);
                if (l.type != scene::LightType::Directional)
                    a.sceneEdited |= ImGui::DragFloat3("position", &n.translation.x, 0.01f);
                // Its voxel occlusion mode (--light-occlusion NAME=MODE), from the next frame.
                if (!l.name.empty()) {
                    auto& list = o.settings.lightOcclusion;
                    auto it = std::find_if(list.begin(), list.end(), [&](const auto& e) { return e.first == l.name; });
                    // Spelled as --voxel-occlusion spells it.
                    RenderOptions spelling;
                    spelling.settings.voxelLight.occlusion = it == list.end() ? vxgi::Occlusion::ShadowMap : it->second;
                    std::string mode = findSetting("voxel-occlusion")->text(spelling);
                    if (comboString("voxel occlusion", mode, {"shadowmap", "raycast", "soft", "none"})) {
                        if (it != list.end()) list.erase(it);
                        a.settingsChanged = findSetting("light-occlusion")->parse(o, l.name + "=" + mode);
                    }
                }
                if (l.type != scene::LightType::Point) {
                    glm::vec2 yp = yawPitch(n.rotation);
                    if (ImGui::DragFloat2("direction yaw/pitch", &yp.x, 0.5f, -180.0f, 180.0f)) {
                        n.rotation = fromYawPitch(yp);
                        a.sceneEdited = true;
                    }
                }
                ImGui::TreePop();
            }
            ImGui::PopID();
        }
    }
    if (ImGui::CollapsingHeader("Dynamic objects")) {
        for (size_t i = 0; i < s.nodes.size(); ++i) {
            scene::Node& n = s.nodes[i];
            if (!n.dynamic) continue;
            ImGui::PushID(int(i) + 100000);
            a.sceneEdited |= ImGui::DragFloat3(n.name.empty() ? "node" : n.name.c_str(), &n.translation.x, 0.01f);
            ImGui::PopID();
        }
    }

    if (ImGui::CollapsingHeader("GPU timings", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
            for (const gpu::TimerResult& r : stats.passes) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(r.name.c_str());
                ImGui::TableNextColumn();
                ImGui::Text("%8.3f ms", r.ms);
            }
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted("frame total");
            ImGui::TableNextColumn();
            ImGui::Text("%8.3f ms", stats.gpuMs);
            ImGui::EndTable();
        }
        const float maxMs = std::max(1.0f, *std::max_element(frameMs_.begin(), frameMs_.end()));
        ImGui::PlotLines("frame ms", frameMs_.data(), int(frameMs_.size()), 0, nullptr, 0.0f, maxMs, ImVec2(0, 50));
        ImGui::PlotLines("GPU ms", gpuMs_.data(), int(gpuMs_.size()), 0, nullptr, 0.0f, maxMs, ImVec2(0, 50));
    }
    if (ImGui::CollapsingHeader("GPU memory")) {
        uint64_t total = 0;
        for (const render::MemoryItem& m : renderer.memory()) {
            ImGui::Text("%-22s %9.2f MiB", m.name.c_str(), double(m.bytes) / 1048576.0);
            total += m.bytes;
        }
        ImGui::Text("%-22s %9.2f MiB", "total", double(total) / 1048576.0);
    }
    ImGui::End();
    ImGui::Render();
    return a;
}

void ViewPanel::record(VkCommandBuffer cmd) { ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd); }

}  // namespace dvsgi::app
