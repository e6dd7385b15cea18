// Shared set-up for GPU tests: one Vulkan context per test binary with the
// Khronos validation layer on; every test fails if it raised a validation error.
#pragma once

#include <memory>

#include <gtest/gtest.h>

#include "gpu/context.h"
#include "gpu/tracker.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace dvsgi::test {

gpu::Context& context();

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override { errorsBefore_ = context().validationErrors(); }
    void TearDown() override {
        EXPECT_EQ(context().validationErrors(), errorsBefore_) << "Vulkan validation errors were raised";
    }

private:
    uint32_t errorsBefore_ = 0;
};

// Programmatic scenes: a square of half-size h in the y = 0 plane, normal +Y.
int addMaterial(scene::Scene& s, glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f), bool doubleSided = false);
// A 2x2 texture of one linear (not sRGB) 8-bit colour; returns its index.
int addUniformTexture(scene::Scene& s, uint8_t r, uint8_t g, uint8_t b);
int addQuad(scene::Scene& s, int material, glm::vec3 center, float halfSize, glm::quat rotation = glm::quat(1, 0, 0, 0));
void addTopDownCamera(scene::Scene& s, float height, float yfov);
void addLight(scene::Scene& s, scene::Light light, glm::vec3 position, glm::vec3 direction);
// A unit sphere of 20 * 4^subdivisions triangles, smooth normals, as one primitive.
scene::Primitive icosphere(int subdivisions);
// A node holding `p` with `material`, placed by translation, rotation and scale.
int addMeshNode(scene::Scene& s, scene::Primitive p, int material, glm::vec3 t, glm::quat r, glm::vec3 scale);

image::ImageRGBA32F render(const scene::Scene& s, const render::RenderSettings& settings);

// A tracker for passes run outside a Renderer: it knows the volumes' state
// after construction (zeroed, gpu::use::ComputeReadWrite).
gpu::Tracker volumeTracker(const vxgi::VoxelVolumes& volumes);

// World point on the plane y = planeY seen through the centre of pixel (x, y).
glm::vec3 pixelOnPlane(const scene::Scene& s, const render::RenderSettings& settings, uint32_t x, uint32_t y,
                       float planeY);

}  // namespace dvsgi::test
