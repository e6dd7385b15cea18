// libFuzzer target: texture decoding (stb_image through the scene's loader,
// with its size limit) and the downsampling applied for device limits.
#include <cstdint>

#include "scene/import_util.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace dvsgi::scene;
    Texture t;
    std::string error;
    if (!detail::decodeImage(data, size, t, error)) return 0;
    // A decoded texture must hold exactly width x height RGBA texels.
    if (t.rgba8.size() != size_t(t.width) * t.height * 4) __builtin_trap();
    Scene s;
    s.textures.push_back(std::move(t));
    limitTextureSize(s, 16, nullptr);
    const Texture& out = s.textures[0];
    if (out.width > 16 || out.height > 16 || out.rgba8.size() != size_t(out.width) * out.height * 4)
        __builtin_trap();
    return 0;
}
