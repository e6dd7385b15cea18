#include "view_command.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#ifdef DVSGI_HAVE_GLFW

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#define GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <glm/gtc/matrix_transform.hpp>

#include "gpu/check.h"
#include "gpu/context.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "device_faults.h"
#include "render_command.h"
#include "settings_table.h"
#include "scene/scene.h"
#include "view_swapchain.h"

#ifdef DVSGI_HAVE_IMGUI
#include "view_panel.h"
#else
namespace dvsgi::app {
// Built without Dear ImGui: the viewer runs without its panel.
class ViewPanel {
public:
    struct Actions {
        bool settingsChanged = false, sceneEdited = false, recreateSwapchain = false, screenshot = false;
        int camera = -1;
    };
    ViewPanel(const gpu::Context&, GLFWwindow*, const Swapchain&) {}
    Actions build(RenderOptions&, render::Renderer&, const render::FrameStats&, double, float&, const char*) {
        return {};
    }
    void record(VkCommandBuffer) {}
    bool wantsMouse() const { return false; }
    bool wantsKeyboard() const { return false; }
    void setError(std::string) {}
};
}  // namespace dvsgi::app
#endif

#endif

namespace dvsgi::app {

namespace {

// Interactive frames never block on converging: with --bounces auto every
// frame adds one bounce from the previous frame's light.
[[maybe_unused]] render::RenderSettings viewSettings(const RenderOptions& o) {
    render::RenderSettings rs = o.settings;
    if (rs.voxelLight.bounceMode == vxgi::BounceMode::Converge) rs.voxelLight.bounceMode = vxgi::BounceMode::Feedback;
    return rs;
}

// One line and a non-zero exit when there is no display to open a window on.
const char* const kNoDisplay =
    "dvsgi: view needs a display (DISPLAY is not set); use dvsgi render for headless output\n";

bool haveDisplay() {
    const char* d = std::getenv("DISPLAY");
    const char* w = std::getenv("WAYLAND_DISPLAY");
    return (d && *d) || (w && *w);
}

}  // namespace

#ifndef DVSGI_HAVE_GLFW

bool viewAvailable() { return false; }

int runView(const RenderOptions&) {
    if (!haveDisplay()) {
        std::fputs(kNoDisplay, stderr);
        return 1;
    }
    std::fprintf(stderr, "dvsgi: this build has no viewer (GLFW was not found when it was configured); "
                         "use dvsgi render\n");
    return 1;
}

#else

bool viewAvailable() { return true; }

namespace {

std::string g_glfwError;

void glfwErrorCallback(int, const char* text) { g_glfwError = text ? text : "unknown GLFW error"; }

struct GlfwSession {
    ~GlfwSession() { glfwTerminate(); }
};

struct Window {
    GLFWwindow* handle = nullptr;
    ~Window() {
        if (handle) glfwDestroyWindow(handle);
    }
};

struct Surface {
    VkInstance instance = VK_NULL_HANDLE;
    VkSurfaceKHR handle = VK_NULL_HANDLE;
    ~Surface() {
        if (handle) vkDestroySurfaceKHR(instance, handle, nullptr);
    }
};

// Fly camera: position, yaw about +Y (0 = looking down -Z) and pitch.
struct FlyCamera {
    glm::vec3 position{0.0f};
    float yaw = 0.0f, pitch = 0.0f;
    float speed = 1.0f;  // metres per second

    void setFrom(const glm::mat4& world) {
        position = glm::vec3(world[3]);
        const glm::vec3 f = glm::normalize(-glm::vec3(world[2]));
        pitch = std::asin(std::clamp(f.y, -1.0f, 1.0f));
        yaw = std::atan2(f.x, -f.z);
    }
    glm::mat4 world() const {
        glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
        m = glm::rotate(m, -yaw, glm::vec3(0, 1, 0));
        return glm::rotate(m, pitch, glm::vec3(1, 0, 0));
    }
};

// Appends the camera's pose to `path` and rewrites `file` (a failure is
// reported; the window stays open). Keys need increasing times: a second key
// in the same frame is dropped.
void recordKey(scene::CameraPath& path, const render::Renderer& renderer, float time, const std::string& file) {
    if (!path.keys.empty() && !(time > path.keys.back().time)) return;
    scene::CameraKey key;
    key.time = time;
    key.position = glm::vec3(renderer.camera().world[3]);
    key.orientation = glm::normalize(glm::quat_cast(glm::mat3(renderer.camera().world)));
    key.yfov = renderer.camera().camera.yfov;
    path.keys.push_back(key);
    try {
        std::filesystem::path parent = std::filesystem::path(file).parent_path();
        if (!parent.empty()) std::filesystem::create_directories(parent);
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out << scene::cameraPathJson(path);
        if (!out) throw std::runtime_error("cannot write the file");
        std::printf("camera key %zu at %.2f s -> %s\n", path.keys.size(), time, file.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "dvsgi: --record-path %s: %s\n", file.c_str(), e.what());
    }
}

// Objects the keys can move: lights, then dynamic nodes.
std::vector<int> movableNodes(const scene::Scene& s) {
    std::vector<int> out;
    for (size_t i = 0; i < s.nodes.size(); ++i)
        if (s.nodes[i].light >= 0) out.push_back(int(i));
    for (size_t i = 0; i < s.nodes.size(); ++i)
        if (s.nodes[i].dynamic && s.nodes[i].light < 0) out.push_back(int(i));
    return out;
}

// The screenshot: the renderer's output as EXR (linear radiance) and the PNG
// preview beside it, exactly as `dvsgi render` writes them.
void writeScreenshot(const render::Renderer& renderer, const std::string& exr, float exposure) {
    const image::ImageRGBA32F img = renderer.readOutput();
    image::writeExr(exr, img);
    const std::string png = std::filesystem::path(exr).replace_extension(".png").string();
    image::writePng(png, img, exposure);
    std::printf("wrote %s and %s\n", exr.c_str(), png.c_str());
}

struct Input {
    double scroll = 0.0;
    std::vector<int> pressed;  // keys pressed since the last frame
};

void keyCallback(GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_PRESS) static_cast<Input*>(glfwGetWindowUserPointer(w))->pressed.push_back(key);
}

void scrollCallback(GLFWwindow* w, double, double dy) {
    static_cast<Input*>(glfwGetWindowUserPointer(w))->scroll += dy;
}

}  // namespace

int runView(const RenderOptions& options) {
    if (!haveDisplay()) {
        std::fputs(kNoDisplay, stderr);
        return 1;
    }
    RenderOptions o = options;
    glfwSetErrorCallback(glfwErrorCallback);
    if (!glfwInit()) {
        std::fprintf(stderr, "dvsgi: view cannot open the display: %s\n", g_glfwError.c_str());
        return 1;
    }
    GlfwSession glfw;
    if (!glfwVulkanSupported()) {
        std::fprintf(stderr, "dvsgi: view: GLFW found no Vulkan loader with surface support\n");
        return 1;
    }

    scene::Scene loaded = loadForOptions(o);
    for (const std::string& w : loaded.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    Window window;
    window.handle = glfwCreateWindow(int(o.settings.width), int(o.settings.height), "dvsgi view", nullptr, nullptr);
    if (!window.handle) {
        std::fprintf(stderr, "dvsgi: view cannot create a window: %s\n", g_glfwError.c_str());
        return 1;
    }
    Input input;
    glfwSetWindowUserPointer(window.handle, &input);
    glfwSetKeyCallback(window.handle, keyCallback);
    glfwSetScrollCallback(window.handle, scrollCallback);

    gpu::ContextOptions co;
    co.validation = o.validate;
    co.deviceName = o.device;
    co.printDevice = !o.quiet;
    co.swapchain = true;
    uint32_t extCount = 0;
    const char** exts = glfwGetRequiredInstanceExtensions(&extCount);
    co.instanceExtensions.assign(exts, exts + extCount);
    gpu::Context ctx(co);

    Surface surface;
    surface.instance = ctx.instance;
    VK_CHECK(glfwCreateWindowSurface(ctx.instance, window.handle, nullptr, &surface.handle));
    Swapchain swapchain(ctx, surface.handle);

    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window.handle, &fbw, &fbh);
    o.settings.width = uint32_t(std::max(fbw, 1));
    o.settings.height = uint32_t(std::max(fbh, 1));
    swapchain.create(o.settings.width, o.settings.height, o.vsync);

    const std::optional<scene::CameraPath> cameraPath = cameraPathFor(o);
    auto makeRenderer = [&](const scene::Scene& s) {
        auto r = std::make_unique<render::Renderer>(ctx, s, viewSettings(o));
        for (const std::string& w : r->warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
        if (cameraPath) r->setCameraPath(cameraPath);
        return r;
    };
    std::unique_ptr<render::Renderer> renderer = makeRenderer(loaded);
    loaded = scene::Scene{};
    ViewPanel panel(ctx, window.handle, swapchain);  // after our callbacks: ImGui chains them
    // Rebuilds after a change of options; on failure (out of memory at a large
    // window, say) the message is printed and shown in the panel, the previous
    // options come back and the previous renderer stays. Returns whether it was rebuilt.
    auto rebuild = [&](const RenderOptions& previous) {
        try {
            renderer = makeRenderer(renderer->scene());
            panel.setError("");
            return true;
        } catch (const gpu::GpuError& e) {
            // A lost device cannot draw the old renderer either: that ends the viewer.
            if (e.result == VK_ERROR_DEVICE_LOST) throw;
            const std::string message = describeGpuError(e, o) + " (setting reverted)";
            std::fprintf(stderr, "dvsgi: %s\n", message.c_str());
            panel.setError(message);
        } catch (const std::exception& e) {
            const std::string message = withFlagNames(e.what());
            std::fprintf(stderr, "dvsgi: %s (setting reverted)\n", message.c_str());
            panel.setError(message + " (setting reverted)");
        }
        o = previous;
        return false;
    };
    // A panel change: from the next frame when the renderer can take it, else
    // (new resources needed) a new renderer.
    auto applyOrRebuild = [&](const RenderOptions& previous) {
        try {
            if (renderer->applySettings(viewSettings(o))) return true;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "dvsgi: %s (setting reverted)\n", withFlagNames(e.what()).c_str());
            o = previous;
            renderer->applySettings(viewSettings(o));
            return false;
        }
        return rebuild(previous);
    };

    FlyCamera fly;
    fly.setFrom(renderer->camera().world);
    {
        const scene::Scene& s = renderer->scene();
        const scene::Bounds b = scene::worldBounds(s, scene::drawItems(s, scene::worldMatrices(s)));
        if (b.valid()) fly.speed = std::max(0.25f * glm::length(b.max - b.min), 1e-3f);
    }
    size_t selected = 0;  // index into movableNodes()
    uint32_t frame = 0, screenshots = 0;
    double lastMouseX = 0.0, lastMouseY = 0.0;
    bool looking = false, screenshotWanted = false;
    auto last = std::chrono::steady_clock::now();
    auto titleTime = last;
    double frameMsAvg = 0.0;
    render::FrameStats stats;
    const bool animated = !renderer->scene().animations.empty() || cameraPath;
    // K appends the camera's pose at the current time to a path written to --record-path.
    scene::CameraPath recorded;
    recorded.catmullRom = true;

    while (!glfwWindowShouldClose(window.handle)) {
        glfwPollEvents();
        const auto now = std::chrono::steady_clock::now();
        const float frameSeconds = std::chrono::duration<float>(now - last).count();
        const float dt = std::min(frameSeconds, 0.25f);  // movement step: no jumps after a stall
        last = now;

        // Resize: recreate the swapchain and the renderer at the new size.
        glfwGetFramebufferSize(window.handle, &fbw, &fbh);
        if (fbw == 0 || fbh == 0) {
            glfwWaitEvents();
            continue;
        }
        if (uint32_t(fbw) != o.settings.width || uint32_t(fbh) != o.settings.height) {
            const RenderOptions previous = o;
            o.settings.width = uint32_t(fbw);
            o.settings.height = uint32_t(fbh);
            swapchain.create(o.settings.width, o.settings.height, o.vsync);
            rebuild(previous);  // on failure the old-size frame is shown scaled
        }

        // The panel first: it says whether the mouse and keys are its own.
        bool cameraMoved = false, objectMoved = false;
        const RenderOptions before = o;
        const ViewPanel::Actions ui =
            panel.build(o, *renderer, stats, frameSeconds * 1000.0, fly.speed, swapchain.presentModeName());
        if (panel.wantsKeyboard()) input.pressed.clear();  // typing into the panel
        int wantCamera = ui.camera;
        if (ui.screenshot) input.pressed.push_back(GLFW_KEY_P);
        if (ui.recreateSwapchain) swapchain.create(o.settings.width, o.settings.height, o.vsync);
        if (ui.settingsChanged) applyOrRebuild(before);
        objectMoved = ui.sceneEdited;

        // Discrete keys.
        for (int key : input.pressed) {
            if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window.handle, GLFW_TRUE);
            if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9) wantCamera = key - GLFW_KEY_1;
            if (key == GLFW_KEY_V) {
                o.vsync = !o.vsync;
                swapchain.create(o.settings.width, o.settings.height, o.vsync);
                std::printf("present mode: %s\n", swapchain.presentModeName());
            }
            if (key == GLFW_KEY_P) screenshotWanted = true;
            if (key == GLFW_KEY_K) recordKey(recorded, *renderer, float(frame) * o.timeStep, o.recordPath);
            if (key == GLFW_KEY_TAB) ++selected;
        }
        input.pressed.clear();
        if (wantCamera >= 0 && wantCamera != o.settings.camera) {
            const size_t cameras =
                scene::placedCameras(renderer->scene(), scene::worldMatrices(renderer->scene())).size();
            if (size_t(wantCamera) < cameras) {
                const RenderOptions previous = o;
                o.settings.camera = wantCamera;
                if (rebuild(previous)) fly.setFrom(renderer->camera().world);
            }
        }
        if (panel.wantsMouse()) input.scroll = 0.0;
        if (input.scroll != 0.0) {
            fly.speed *= float(std::pow(1.25, input.scroll));
            input.scroll = 0.0;
        }

        // Continuous keys: fly camera and the selected object.
        const bool keys = !panel.wantsKeyboard();
        auto down = [&](int k) { return keys && glfwGetKey(window.handle, k) == GLFW_PRESS; };
        const float step = fly.speed * dt * (down(GLFW_KEY_LEFT_SHIFT) ? 4.0f : 1.0f);
        const glm::mat4 cw = fly.world();
        const glm::vec3 right(cw[0]), forward(-cw[2]), up(0, 1, 0);
        glm::vec3 move(0.0f);
        if (down(GLFW_KEY_W)) move += forward;
        if (down(GLFW_KEY_S)) move -= forward;
        if (down(GLFW_KEY_D)) move += right;
        if (down(GLFW_KEY_A)) move -= right;
        if (down(GLFW_KEY_E)) move += up;
        if (down(GLFW_KEY_Q)) move -= up;
        if (move != glm::vec3(0.0f)) {
            fly.position += step * move;
            cameraMoved = true;
        }
        double mx = 0.0, my = 0.0;
        glfwGetCursorPos(window.handle, &mx, &my);
        const bool rightDown = glfwGetMouseButton(window.handle, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
        if (rightDown && (looking || !panel.wantsMouse())) {
            if (looking && (mx != lastMouseX || my != lastMouseY)) {
                fly.yaw += float(mx - lastMouseX) * 0.003f;
                fly.pitch = std::clamp(fly.pitch - float(my - lastMouseY) * 0.003f, -1.55f, 1.55f);
                cameraMoved = true;
            }
            looking = true;
        } else {
            looking = false;
        }
        lastMouseX = mx;
        lastMouseY = my;

        scene::Scene& sc = renderer->scene();
        const std::vector<int> movable = movableNodes(sc);
        if (!movable.empty()) {
            glm::vec3 d(0.0f);
            if (down(GLFW_KEY_RIGHT)) d.x += 1.0f;
            if (down(GLFW_KEY_LEFT)) d.x -= 1.0f;
            if (down(GLFW_KEY_UP)) d.z -= 1.0f;
            if (down(GLFW_KEY_DOWN)) d.z += 1.0f;
            if (down(GLFW_KEY_PAGE_UP)) d.y += 1.0f;
            if (down(GLFW_KEY_PAGE_DOWN)) d.y -= 1.0f;
            if (d != glm::vec3(0.0f)) {
                sc.nodes[size_t(movable[selected % movable.size()])].translation += step * d;
                objectMoved = true;
            }
        }
        if (cameraMoved) {
            const int node = scene::placedCameraNode(sc, o.settings.camera);
            if (node >= 0) scene::setNodeWorld(sc, node, fly.world());
        }
        // Same frame sequence as `dvsgi render --frames K`: fixed time steps.
        if (animated)
            renderer->setTime(float(frame) * o.timeStep);  // also applies the edits above
        else if (cameraMoved || objectMoved)
            renderer->sceneChanged();  // moved objects trigger the dynamic update

        stats = renderer->renderFrame();
        // After the frame, so the file holds what this renderer just drew
        // (a rebuild earlier in the loop leaves an output never rendered).
        if (screenshotWanted) {
            screenshotWanted = false;
            const std::string path =
                o.screenshot.empty() ? "out/view_" + std::to_string(screenshots) + ".exr" : o.screenshot;
            try {  // a failed screenshot is reported; the window stays open
                writeScreenshot(*renderer, path, o.exposure);
                ++screenshots;
            } catch (const std::exception& e) {
                std::fprintf(stderr, "dvsgi: screenshot: %s\n", e.what());
            }
        }
        if (!swapchain.present(renderer->outputImage(), o.exposure, [&](VkCommandBuffer cmd) { panel.record(cmd); }))
            swapchain.create(o.settings.width, o.settings.height, o.vsync);
        ++frame;

        frameMsAvg = frame == 1 ? frameSeconds * 1000.0 : 0.9 * frameMsAvg + 0.1 * frameSeconds * 1000.0;
        if (std::chrono::duration<double>(now - titleTime).count() > 0.5) {
            titleTime = now;
            std::string title = "dvsgi view - " + std::to_string(int(1000.0 / std::max(frameMsAvg, 1e-3))) +
                                " fps, GPU " + std::to_string(int(stats.gpuMs)) + " ms, " + swapchain.presentModeName();
            if (!movable.empty()) {
                const scene::Node& n = sc.nodes[size_t(movable[selected % movable.size()])];
                title += ", moving '" + n.name + "' (Tab: next)";
            }
            glfwSetWindowTitle(window.handle, title.c_str());
        }
        if (o.viewFrames > 0 && frame >= o.viewFrames) glfwSetWindowShouldClose(window.handle, GLFW_TRUE);
    }

    vkDeviceWaitIdle(ctx.device);
    if (!o.screenshot.empty() && frame > 0) writeScreenshot(*renderer, o.screenshot, o.exposure);
    if (!o.quiet) {
        std::printf("%-24s %10s\n", "pass", "GPU ms");
        for (const gpu::TimerResult& r : stats.passes) std::printf("%-24s %10.3f\n", r.name.c_str(), r.ms);
        std::printf("%-24s %10.3f\n", "frame total", stats.gpuMs);
        std::printf("view: %u frame(s), %ux%u, %s\n", frame, o.settings.width, o.settings.height, swapchain.presentModeName());
    }
    renderer.reset();
    if (ctx.validationErrors() > 0) {
        std::fprintf(stderr, "dvsgi: %u Vulkan validation error(s)\n", ctx.validationErrors());
        return 3;
    }
    return 0;
}

#endif  // DVSGI_HAVE_GLFW

}  // namespace dvsgi::app
