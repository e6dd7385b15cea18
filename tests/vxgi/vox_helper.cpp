#include "vox_helper.h"

#include <cstring>

#include "gpu/transfer.h"
#include "gpu_fixture.h"

namespace dvsgi::test {

VoxelSet VoxelReadback::occupancy() const {
    VoxelSet s(n);
    for (int z = 0; z < int(n); ++z)
        for (int y = 0; y < int(n); ++y)
            for (int x = 0; x < int(n); ++x)
                if (count(x, y, z) > 0.0f) s.set(x, y, z);
    return s;
}

VoxelReadback readVoxels(const vxgi::VoxelVolumes& volumes) {
    // The per-slot sums scattered back to the grid through the index.
    return VoxelReadback{vxgi::readAttributes(context(), volumes)};
}

std::vector<uint32_t> readExtents(const vxgi::VoxelVolumes& v) {
    const std::vector<uint8_t> index = gpu::readbackBuffer(context(), v.index);
    const std::vector<uint8_t> extents = gpu::readbackBuffer(context(), v.extents);
    std::vector<uint32_t> out(size_t(v.grid.n) * v.grid.n * v.grid.n, 0u);
    for (size_t i = 0; i < out.size(); ++i) {
        uint32_t value = 0;
        std::memcpy(&value, index.data() + 4 * i, 4);
        const uint32_t slot1 = shader::indexSlot(value);
        if (slot1 != 0) std::memcpy(&out[i], extents.data() + 4 * size_t(slot1 - 1), 4);
    }
    return out;
}

std::string voxelizerTestName(const ::testing::TestParamInfo<vxgi::VoxelizerKind>& info) {
    return vxgi::voxelizerName(info.param);
}

VoxelRig::VoxelRig(const scene::Scene& scene, const vxgi::GridSpec& grid, vxgi::VoxelizerKind kind, uint32_t slots)
    : sceneGpu(context(), scene, float(render::RenderSettings{}.textureAnisotropy)),
      voxelizer(context(), sceneGpu, false, kind),
      list(context()),
      volumes(context(), grid, slots),
      tracker(volumeTracker(volumes)) {}

void VoxelRig::fullVoxelize() {
    context().submitAndWait([&](VkCommandBuffer cmd) {
        voxelizer.clearAll(cmd, tracker, volumes, nullptr);
        list.reset(cmd, tracker, volumes);
        voxelizer.voxelize(cmd, tracker, sceneGpu, volumes, vxgi::VoxelizeMode::Static, nullptr);
        list.finish(cmd, tracker, volumes, true);
        voxelizer.voxelize(cmd, tracker, sceneGpu, volumes, vxgi::VoxelizeMode::Dynamic, nullptr);
        list.finish(cmd, tracker, volumes, false);
    });
}

void VoxelRig::dynamicFrame() {
    context().submitAndWait([&](VkCommandBuffer cmd) {
        voxelizer.clearDynamic(cmd, tracker, volumes, nullptr);
        list.dropDynamic(cmd, tracker, volumes);
        voxelizer.voxelize(cmd, tracker, sceneGpu, volumes, vxgi::VoxelizeMode::Dynamic, nullptr);
        list.finish(cmd, tracker, volumes, false);
    });
}

void VoxelRig::updateTransforms(const scene::Scene& scene) {
    sceneGpu.updateDraws(context(), scene, scene::drawItems(scene, scene::worldMatrices(scene)));
}

VoxelReadback voxelizeScene(const scene::Scene& scene, const vxgi::GridSpec& grid, vxgi::VoxelizerKind kind) {
    VoxelRig rig(scene, grid, kind);
    rig.fullVoxelize();
    return rig.read();
}

namespace {

int addPrimitiveNode(scene::Scene& s, scene::Primitive p, glm::vec3 translation, bool dynamic) {
    s.primitives.push_back(std::move(p));
    scene::Mesh mesh;
    mesh.name = "mesh" + std::to_string(s.meshes.size());
    mesh.primitives = {uint32_t(s.primitives.size() - 1)};
    s.meshes.push_back(mesh);
    scene::Node n;
    n.name = "node" + std::to_string(s.nodes.size());
    n.mesh = int(s.meshes.size() - 1);
    n.translation = translation;
    n.dynamic = dynamic;
    s.nodes.push_back(n);
    s.roots.push_back(int(s.nodes.size() - 1));
    return int(s.nodes.size() - 1);
}

void pushTriangle(scene::Primitive& p, const WorldTriangle& t, glm::vec3 normal) {
    for (const glm::vec3& c : t) {
        scene::Vertex v;
        v.position = c;
        v.normal = normal;
        p.indices.push_back(uint32_t(p.vertices.size()));
        p.vertices.push_back(v);
    }
}

}  // namespace

int addTriangles(scene::Scene& s, int material, const std::vector<WorldTriangle>& tris, glm::vec3 translation,
                 bool dynamic) {
    scene::Primitive p;
    p.material = uint32_t(material);
    for (const WorldTriangle& t : tris) {
        glm::vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
        const float len = glm::length(n);
        pushTriangle(p, t, len > 0.0f ? n / len : glm::vec3(0, 1, 0));
    }
    return addPrimitiveNode(s, std::move(p), translation, dynamic);
}

int addRect(scene::Scene& s, int material, glm::vec3 lo, glm::vec3 hi, int axis, float normalSign) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    auto corner = [&](bool hu, bool hv) {
        glm::vec3 c = lo;
        c[u] = hu ? hi[u] : lo[u];
        c[v] = hv ? hi[v] : lo[v];
        return c;
    };
    glm::vec3 normal(0.0f);
    normal[axis] = normalSign;
    scene::Primitive p;
    p.material = uint32_t(material);
    pushTriangle(p, {corner(false, false), corner(true, false), corner(true, true)}, normal);
    pushTriangle(p, {corner(false, false), corner(true, true), corner(false, true)}, normal);
    return addPrimitiveNode(s, std::move(p), glm::vec3(0.0f), false);
}

int addBox(scene::Scene& s, int material, glm::vec3 h, glm::vec3 translation, bool dynamic) {
    scene::Primitive p;
    p.material = uint32_t(material);
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            auto corner = [&](float su, float sv) {
                glm::vec3 c;
                c[axis] = sign * h[axis];
                c[u] = su * h[u];
                c[v] = sv * h[v];
                return c;
            };
            glm::vec3 normal(0.0f);
            normal[axis] = sign;
            pushTriangle(p, {corner(-1, -1), corner(1, -1), corner(1, 1)}, normal);
            pushTriangle(p, {corner(-1, -1), corner(1, 1), corner(-1, 1)}, normal);
        }
    return addPrimitiveNode(s, std::move(p), translation, dynamic);
}

glm::dvec3 toVoxel(const glm::vec3& world, const vxgi::GridSpec& grid) {
    const glm::vec3 v = (world - grid.origin) / grid.voxelSize;
    return glm::dvec3(v);
}

std::vector<Triangle> voxelTriangles(const scene::Scene& scene, const vxgi::GridSpec& grid) {
    std::vector<Triangle> out;
    const std::vector<glm::mat4> world = scene::worldMatrices(scene);
    for (const scene::DrawItem& it : scene::drawItems(scene, world)) {
        const scene::Primitive& p = scene.primitives[it.primitive];
        for (size_t i = 0; i + 2 < p.indices.size(); i += 3) {
            Triangle t;
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 w = glm::vec3(it.world * glm::vec4(p.vertices[p.indices[i + size_t(k)]].position, 1.0f));
                t.v[k] = toVoxel(w, grid);
            }
            out.push_back(t);
        }
    }
    return out;
}

}  // namespace dvsgi::test
