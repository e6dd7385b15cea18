#include "vxgi/cone_settings.h"

namespace dvsgi::vxgi {

ConeSettings bounceCones(const ConeSettings& shared, float bounceStepFactor) {
    ConeSettings c = shared;
    c.coneSet = shader::CONE_SET_6;
    c.stepFactor = bounceStepFactor;
    c.offsetVoxels = 2.0f;
    return c;
}

shader::ConeParams gpuCone(const ConeSettings& c, const GridSpec& grid) {
    const float diagonal = grid.voxelSize * float(grid.n) * 1.7320508f;
    return shader::ConeParams{
        glm::vec4(c.stepFactor, c.minStepVoxels, c.maxDistance > 0.0f ? c.maxDistance : diagonal,
                  c.firstSampleVoxels),
        glm::vec4(c.clearance, shader::CONE_SURFACE_VOXELS, c.offsetVoxels, float(c.coneSet))};
}

}  // namespace dvsgi::vxgi
