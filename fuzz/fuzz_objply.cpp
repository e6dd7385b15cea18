// libFuzzer target: the OBJ/PLY import path (pre-checks, then assimp, then
// the conversion and loadScene's checks) on bytes in memory. Input starting
// with "ply" is a PLY file, anything else an OBJ, so seeds need no prefix.
#include <cstdint>
#include <cstring>

#include "scene/load.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace dvsgi::scene;
    const bool ply = size >= 3 && std::memcmp(data, "ply", 3) == 0;
    try {
        Scene s = loadWithAssimpFromMemory(ply ? "input.ply" : "input.obj", ply ? ".ply" : ".obj", data, size);
        validateScene(s);
        addDefaults(s);
    } catch (const LoadError&) {
    }
    return 0;
}
