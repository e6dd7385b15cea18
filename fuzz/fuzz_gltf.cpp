// libFuzzer target: the glTF/GLB parser on bytes in memory, followed by the
// checks loadScene applies. A LoadError is the expected answer to bad input;
// any other exception escapes and libFuzzer reports it, because the CLI would
// print it without naming the file.
#include <cstdint>
#include <vector>

#include "scene/load.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace dvsgi::scene;
    std::vector<uint8_t> bytes(data, data + size);
    try {
        // The folder does not exist: relative URIs find nothing, and the
        // confinement refuses everything else, so no file is ever read.
        Scene s = loadGltfFromMemory("fuzz-no-such-dir/input.gltf", bytes);
        validateScene(s);
        addDefaults(s);
        limitTextureSize(s, 64, nullptr);
    } catch (const LoadError&) {
    }
    return 0;
}
