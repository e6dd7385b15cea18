// dvsgi command-line entry point: parse, dispatch, and turn every failure into
// one line on stderr with a non-zero exit code. Library messages about a
// setting start with its name, which becomes the flag here.
#include <cstdio>
#include <exception>
#include <new>

#include "bench_command.h"
#include "device_faults.h"
#include "gpu/check.h"
#include "image/image_io.h"
#include "options.h"
#include "render_command.h"
#include "settings_table.h"
#include "soak_command.h"
#include "view_command.h"
#include "scene/load.h"

int main(int argc, char** argv) {
    using namespace dvsgi;
    const app::ParseResult parsed = app::parseCommandLine(argc, argv);
    if (!parsed.error.empty()) {
        std::fprintf(stderr, "dvsgi: %s\n", parsed.error.c_str());
        return 2;
    }
    try {
        switch (parsed.command) {
            case app::Command::Help: std::fputs(app::usageText().c_str(), stdout); return 0;
            case app::Command::Version: std::puts("dvsgi 0.1.0"); return 0;
            case app::Command::Render: return app::runRender(parsed.render);
            case app::Command::View: return app::runView(parsed.render);
            case app::Command::Bench: return app::runBench(parsed.render);
            case app::Command::Soak: return app::runSoak(parsed.render);
        }
    } catch (const scene::LoadError& e) {
        std::fprintf(stderr, "dvsgi: %s\n", e.what());
    } catch (const image::IoError& e) {
        std::fprintf(stderr, "dvsgi: %s\n", e.what());
    } catch (const gpu::GpuError& e) {
        std::fprintf(stderr, "dvsgi: %s\n", app::withFlagNames(app::describeGpuError(e, parsed.render)).c_str());
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "dvsgi: out of host memory\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "dvsgi: %s\n", app::withFlagNames(e.what()).c_str());
    }
    return 1;
}
