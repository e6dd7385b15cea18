// The occupied-voxel list and the slot index against the attributes they
// address: every occupied voxel once, static entries first, each voxel's index
// naming its own entry (its slot) with the static bit where static geometry
// claimed it, dispatch arguments that cover exactly the entries, and a dynamic
// clear that empties what dynamic geometry left (attributes, direct light,
// radiance, index).
#include <algorithm>
#include <cstring>
#include <set>

#include <gtest/gtest.h>

#include "gpu/transfer.h"
#include "gpu_fixture.h"
#include "shared/voxel_list_pass.h"
#include "vox_helper.h"
#include "vxgi/voxel_storage_io.h"

namespace dvsgi::test {
namespace {

namespace sh = dvsgi::shader;

class VoxelList : public GpuTest, public ::testing::WithParamInterface<vxgi::VoxelizerKind> {};

const vxgi::GridSpec kGrid = exactGrid(glm::vec3(0.0f), 1.0f, 32);

struct ListReadback {
    sh::VoxelListHeader header{};
    std::vector<glm::ivec3> entries;
};

ListReadback readList(const vxgi::VoxelVolumes& volumes) {
    const std::vector<uint8_t> bytes = gpu::readbackBuffer(context(), volumes.list);
    ListReadback r;
    std::memcpy(&r.header, bytes.data(), sizeof(r.header));
    const uint32_t count = std::min(r.header.counts.x, r.header.counts.z);
    for (uint32_t i = 0; i < count; ++i) {
        uint32_t e;
        std::memcpy(&e, bytes.data() + sizeof(r.header) + size_t(i) * 4, 4);
        r.entries.push_back(sh::unpackVoxel(e));
    }
    return r;
}

glm::uvec3 expectedGroups(uint32_t entries) {
    const uint32_t groups = (entries + sh::VOXEL_LIST_GROUP - 1) / sh::VOXEL_LIST_GROUP;
    const uint32_t x = std::min(groups, sh::VOXEL_LIST_ROW);
    return {x, x == 0 ? 0 : (groups + x - 1) / x, 1};
}

// The list holds each voxel of `occupied` exactly once and nothing else; its
// first `statics` entries are the voxels of `staticSet`.
void expectListMatches(const ListReadback& list, const VoxelSet& occupied, const VoxelSet& staticSet) {
    EXPECT_EQ(list.header.counts.w, 0u) << "entries dropped";
    EXPECT_EQ(list.header.counts.x, occupied.count());
    EXPECT_EQ(list.header.counts.y, staticSet.count());
    std::set<std::tuple<int, int, int>> seen;
    for (size_t i = 0; i < list.entries.size(); ++i) {
        const glm::ivec3 v = list.entries[i];
        EXPECT_TRUE(seen.insert({v.x, v.y, v.z}).second) << "voxel listed twice: " << v.x << " " << v.y << " " << v.z;
        EXPECT_TRUE(occupied.get(v.x, v.y, v.z)) << "empty voxel listed: " << v.x << " " << v.y << " " << v.z;
        EXPECT_EQ(staticSet.get(v.x, v.y, v.z), i < list.header.counts.y)
            << "entry " << i << " on the wrong side of the static count";
    }
    const glm::uvec3 all = expectedGroups(list.header.counts.x);
    const glm::uvec3 dyn = expectedGroups(list.header.counts.x - list.header.counts.y);
    EXPECT_EQ(glm::uvec3(list.header.allGroups), all);
    EXPECT_EQ(glm::uvec3(list.header.dynamicGroups), dyn);
}

// Voxel v's index holds slot + 1 of its list entry, static where the entry
// is; every other voxel's index is 0.
void expectIndexMatches(const vxgi::VoxelVolumes& volumes, const ListReadback& list) {
    const std::vector<uint32_t> index = vxgi::readVoxelIndex(context(), volumes);
    const uint32_t n = volumes.grid.n;
    std::vector<bool> listed(index.size(), false);
    for (size_t i = 0; i < list.entries.size(); ++i) {
        const glm::ivec3 v = list.entries[i];
        const size_t at = (size_t(v.z) * n + size_t(v.y)) * n + size_t(v.x);
        listed[at] = true;
        const uint32_t want = uint32_t(i + 1) | (i < list.header.counts.y ? sh::VOXEL_INDEX_STATIC : 0u);
        EXPECT_EQ(index[at], want) << "entry " << i;
    }
    size_t stray = 0;
    for (size_t i = 0; i < index.size(); ++i) stray += !listed[i] && index[i] != 0;
    EXPECT_EQ(stray, 0u) << "voxels with an index but no entry";
}

void addStatic(scene::Scene& s) {
    addRect(s, addMaterial(s, glm::vec3(0.8f, 0.7f, 0.6f)), {4, 2.5f, 4}, {28, 2.5f, 28}, 1, 1.0f);
    addBox(s, addMaterial(s, glm::vec3(0.1f, 0.9f, 0.2f)), glm::vec3(1.25f, 4.0f, 1.25f),
           glm::vec3(20.5f, 6.5f, 12.5f), false);
}

std::vector<uint16_t> halfOnes(uint32_t n) { return std::vector<uint16_t>(size_t(n) * n * n * 4, 0x3C00); }

TEST_P(VoxelList, HoldsEveryOccupiedVoxelOnceStaticFirstAsADynamicBoxMoves) {
    scene::Scene s;
    addStatic(s);
    scene::Scene staticOnly = s;
    const int box = addBox(s, addMaterial(s, glm::vec3(0.3f, 0.2f, 0.9f)), glm::vec3(1.5f, 1.5f, 1.25f),
                           glm::vec3(8.3f, 3.6f, 8.7f), true);
    VoxelRig staticRig(staticOnly, kGrid, GetParam());
    staticRig.fullVoxelize();
    const VoxelSet staticSet = staticRig.read().occupancy();
    ASSERT_GT(staticSet.count(), 0u);

    VoxelRig rig(s, kGrid, GetParam());
    rig.fullVoxelize();
    VoxelSet occupied = rig.read().occupancy();
    expectListMatches(readList(rig.volumes), occupied, staticSet);
    expectIndexMatches(rig.volumes, readList(rig.volumes));

    // Through the pillar (voxels shared with static geometry stay static), then in the open.
    const glm::vec3 positions[] = {{21.75f, 3.0f, 13.5f}, {14.1f, 6.2f, 11.4f}, {15.0f, 20.0f, 15.0f}};
    for (const glm::vec3& p : positions) {
        SCOPED_TRACE("box at " + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z));
        // Light everything, so the clear shows in direct light and radiance.
        const std::vector<uint16_t> ones = halfOnes(kGrid.n);
        for (const gpu::Image* img : {&rig.volumes.direct, &rig.volumes.radiance})
            gpu::uploadImage(context(), *img, ones.data(), ones.size() * 2, gpu::use::ComputeReadWrite);
        const VoxelSet before = occupied;
        const uint32_t entriesBefore = readList(rig.volumes).header.counts.x;

        s.nodes[size_t(box)].translation = p;
        rig.updateTransforms(s);
        rig.dynamicFrame();
        occupied = rig.read().occupancy();
        const ListReadback list = readList(rig.volumes);
        expectListMatches(list, occupied, staticSet);
        expectIndexMatches(rig.volumes, list);

        // Voxels the box left read zero radiance; the rest keep theirs.
        const std::vector<uint8_t> radiance =
            gpu::readbackImage(context(), rig.volumes.radiance, gpu::use::ComputeReadWrite);
        size_t vacated = 0, wrong = 0;
        const int n = int(kGrid.n);
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const bool dynamicBefore = before.get(x, y, z) && !staticSet.get(x, y, z);
                    uint16_t h;
                    std::memcpy(&h, radiance.data() + before.index(x, y, z) * 8, 2);
                    const uint16_t want = dynamicBefore ? 0 : 0x3C00;
                    vacated += dynamicBefore;
                    if (h != want && ++wrong <= 5)
                        ADD_FAILURE() << "radiance (" << x << ", " << y << ", " << z << ") = " << h << ", expected "
                                      << want;
                }
        EXPECT_GT(vacated, 0u);
        // Last frame's dynamic slots were zeroed (the new dynamic voxels took
        // them again, unlit until the next voxel light); static slots keep theirs.
        const std::vector<uint8_t> direct =
            gpu::readbackImage(context(), rig.volumes.direct, gpu::use::ComputeReadWrite);
        const uint32_t statics = list.header.counts.y;
        ASSERT_GT(entriesBefore, statics);
        for (uint32_t slot = 0; slot < entriesBefore; ++slot) {
            uint16_t h;
            std::memcpy(&h, direct.data() + size_t(slot) * 8, 2);
            EXPECT_EQ(h, slot < statics ? 0x3C00 : 0) << "direct light of slot " << slot;
        }
    }
}

// The host upload of dense attributes (what the light tests start from)
// gives every voxel with a count one static slot and reads back unchanged.
TEST_P(VoxelList, UploadedAttributesReadBackAndAreListedAsStatic) {
    scene::Scene s;
    addStatic(s);
    VoxelRig rig(s, kGrid, GetParam());
    rig.fullVoxelize();
    const VoxelReadback voxelized = rig.read();
    const VoxelSet occupied = voxelized.occupancy();
    vxgi::VoxelVolumes fresh(context(), kGrid);
    vxgi::uploadAttributes(context(), fresh, voxelized);
    EXPECT_EQ(readVoxels(fresh).data, voxelized.data);
    const ListReadback list = readList(fresh);
    expectListMatches(list, occupied, occupied);
    expectIndexMatches(fresh, list);
}

// A voxelization with fewer slots than occupied voxels counts every claim it
// dropped (the renderer then grows the storage: RendererUpdate tests).
TEST_P(VoxelList, RunningOutOfSlotsCountsTheDroppedClaims) {
    scene::Scene s;
    const int grey = addMaterial(s, glm::vec3(0.5f));
    for (float y = 2.5f; y < 30.0f; y += 4.0f) addRect(s, grey, {1, y, 1}, {31, y, 31}, 1, 1.0f);  // 7 x 900 voxels
    VoxelRig full(s, kGrid, GetParam());
    full.fullVoxelize();
    const uint32_t occupied = uint32_t(full.read().occupancy().count());
    ASSERT_GT(occupied, sh::VOXEL_SLOT_ROW);  // more than the smallest capacity
    VoxelRig small(s, kGrid, GetParam(), sh::VOXEL_SLOT_ROW);
    small.fullVoxelize();
    const ListReadback list = readList(small.volumes);
    EXPECT_EQ(list.header.counts.x, sh::VOXEL_SLOT_ROW);
    EXPECT_EQ(list.header.counts.w, occupied - sh::VOXEL_SLOT_ROW);
    EXPECT_EQ(list.entries.size(), size_t(sh::VOXEL_SLOT_ROW));
}

INSTANTIATE_TEST_SUITE_P(Voxelizers, VoxelList, ::testing::ValuesIn(kVoxelizers), voxelizerTestName);

}  // namespace
}  // namespace dvsgi::test
