// How much a term of the image changes from one frame to the next where the
// scene did not: frame t's term reprojected into frame t+1 through the depth
// buffer and both cameras, compared with frame t+1 (issue #11's flicker
// figure). Pixels that frame t did not see (disocclusion, outside its view,
// sky) are left out, and frame t's term is interpolated only from the pixels
// that saw the same surface (tangent plane and normal). Pure host code on
// read-back images.
#pragma once

#include <cstdint>

#include "image/image_io.h"
#include "scene/scene.h"

namespace dvsgi::render {

class Renderer;

struct TemporalFrame {
    image::ImageRGBA32F term;   // linear radiance (for example the indirect diffuse term)
    // The same light before the surface's albedo (TERM_IRRADIANCE), when
    // captured: what changes of the lighting alone look like, apart from the
    // texture detail a moving camera's resampling changes too.
    image::ImageRGBA32F irradiance;
    image::ImageRGBA32F depth;  // r = distance along the camera axis (m), +inf for no geometry (readSurface)
    image::ImageRGBA32F normal;  // world normal (readSurface); empty: taps are told apart by depth alone
    scene::PlacedCamera camera;
};

struct TemporalChange {
    uint64_t compared = 0;  // pixels of frame t+1 with a matching surface in frame t
    uint64_t rejected = 0;  // pixels with geometry that frame t did not see
    // |Y(t+1) - Y(t)| / max(Y(t), floor) over the compared pixels, floor =
    // 1 % of frame t's mean luminance (so dark pixels do not dominate).
    double meanRelative = 0.0;
    double p99Relative = 0.0;
    double meanLuminanceBefore = 0.0, meanLuminanceAfter = 0.0;  // over the compared pixels
};

enum class TemporalTerm { Term, Irradiance };

// `before` is frame t, `after` frame t+1; both images the same size.
// depthTolerance: relative difference of the reprojected depth above which a
// pixel counts as disoccluded. `which`: compare TemporalFrame::term or ::irradiance.
TemporalChange temporalChange(const TemporalFrame& before, const TemporalFrame& after, float depthTolerance = 0.02f,
                              TemporalTerm which = TemporalTerm::Term);

// The indirect diffuse term, its irradiance and the depth of the renderer's last frame, with its camera.
TemporalFrame captureIndirect(const Renderer& renderer);

}  // namespace dvsgi::render
