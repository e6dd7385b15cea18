// Embedding dvsgi: load a scene, render one 64x64 frame with a 32^3 voxel grid
// and write it as an EXR, with the per-pass GPU times and memory on stdout.
//   embed [SCENE|-] [OUT.exr]      '-' or nothing: the built-in Cornell box
#include <cstdio>
#include <string>

#include <dvsgi/dvsgi.h>

int main(int argc, char** argv) {
    const std::string scenePath = argc > 1 ? argv[1] : "-";
    const std::string out = argc > 2 ? argv[2] : "embed.exr";
    try {
        const dvsgi::Scene scene =
            scenePath == "-" ? dvsgi::Scene::cornellBox() : dvsgi::Scene::load(scenePath);
        for (const std::string& w : scene.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());

        dvsgi::Settings settings;
        settings.width = settings.height = 64;
        settings.voxels = 32;
        dvsgi::Renderer renderer(scene, settings);
        std::printf("dvsgi %s on %s\n", dvsgi::version().c_str(), renderer.deviceName().c_str());

        const dvsgi::FrameInfo frame = renderer.render();
        for (const dvsgi::PassTime& p : frame.passes) std::printf("  %-26s %8.3f ms\n", p.name.c_str(), p.ms);
        std::printf("  %-26s %8.3f ms, %u bounce(s)%s\n", "frame", frame.gpuMs, frame.bounces,
                    frame.converged ? ", converged" : "");
        unsigned long long bytes = 0;
        for (const dvsgi::MemoryUse& m : renderer.memory()) bytes += m.bytes;
        std::printf("  GPU memory %.1f MiB\n", double(bytes) / (1024.0 * 1024.0));

        dvsgi::writeExr(out, renderer.readImage());
        std::printf("wrote %s\n", out.c_str());
        return 0;
    } catch (const dvsgi::Error& e) {
        std::fprintf(stderr, "embed: %s\n", e.what());
        return 1;
    }
}
