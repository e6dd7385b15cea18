// Adding one fragment's material to a voxel: shared by every voxelizer so they
// store exactly the same sums. Needs `grid` (VoxelGrid), `accum` (r32f
// image3D, coherent) and the index (VOXEL_INDEX_BLOCK, coherent) declared by
// the including shader, the occupied-voxel list `list` (writable),
// lib/voxel_index.glsl, and GL_EXT_shader_atomic_float.

// The voxel's index value, claiming a slot when the voxel is empty: the
// invocation whose compare-and-swap finds 0 locks the voxel, takes the next
// list entry as its slot and publishes it; the others retry until the value
// is published. The owner's work sits inside the same loop iteration as the
// others' retry, so lanes of one subgroup reconverge at the loop's end and the
// owner always runs before they look again: a waiting loop placed after the
// owner's branch let NVIDIA's compiler run the waiting lanes first, spinning
// against an owner that could not run until they gave up.
uint claimVoxel(ivec3 voxel, uint mode) {
    uint at = voxelIndexOffset(voxel);
    uint value = voxelIndex[at];
    if (value != 0u && value != VOXEL_INDEX_LOCKED) return value;
    // Bounded: a fragment shader's helper invocations get undefined atomic
    // results (and have no side effects). A real invocation never gets near
    // the bound; if one did, it is counted as dropped, like a full list.
    bool published = false;
    for (uint spins = 0u; spins < VOXEL_CLAIM_SPINS; ++spins) {
        value = atomicCompSwap(voxelIndex[at], 0u, VOXEL_INDEX_LOCKED);
        if (value == 0u) {
            uint slot = atomicAdd(list.header.counts.x, 1u);
            if (slot < list.header.counts.z) {
                list.entries[slot] = packVoxel(storageVoxel(voxel));
                value = slot + 1u;
            } else {
                atomicAdd(list.header.counts.w, 1u);
                value = VOXEL_INDEX_FULL;
            }
            if (mode != VOXELIZE_DYNAMIC) value |= VOXEL_INDEX_STATIC;
            atomicExchange(voxelIndex[at], value);
        }
        if (value != VOXEL_INDEX_LOCKED) {
            published = true;
            break;
        }
    }
    if (!published) {
        atomicAdd(list.header.counts.w, 1u);
        value = VOXEL_INDEX_FULL;
    }
    return value;
}

void accumulateChannel(uint slot, uint channel, float value) {
    if (value != 0.0) imageAtomicAdd(accum, slotTexel(slot, channel), value);
}

// Static voxelization claims voxels as static; dynamic voxelization leaves
// static voxels alone (they are cleared only when static geometry changes).
// After a clipmap scroll, static voxelization writes only the exposed slabs.
// Returns the slot + 1 it added to, or 0 when the fragment was skipped (a
// static voxel under dynamic voxelization, or no slot left: counted for the
// host, which grows the storage and voxelizes again).
uint accumulateFragment(ivec3 voxel, uint mode, vec3 albedo, vec3 emission, vec3 n) {
    if (mode != VOXELIZE_DYNAMIC && keptByScroll(voxel)) return 0u;
    uint value = claimVoxel(voxel, mode);
    if (mode == VOXELIZE_DYNAMIC && (value & VOXEL_INDEX_STATIC) != 0u) return 0u;
    uint slot1 = indexSlot(value);
    if (slot1 == 0u) return 0u;
    uint slot = slot1 - 1u;
    accumulateChannel(slot, CH_ALBEDO_R, albedo.r);
    accumulateChannel(slot, CH_ALBEDO_G, albedo.g);
    accumulateChannel(slot, CH_ALBEDO_B, albedo.b);
    accumulateChannel(slot, CH_COUNT, 1.0);
    accumulateChannel(slot, CH_EMISSION_R, emission.r);
    accumulateChannel(slot, CH_EMISSION_G, emission.g);
    accumulateChannel(slot, CH_EMISSION_B, emission.b);
    vec3 n2 = n * n;
    accumulateChannel(slot, CH_NORMAL_POS_X, n.x > 0.0 ? n2.x : 0.0);
    accumulateChannel(slot, CH_NORMAL_NEG_X, n.x < 0.0 ? n2.x : 0.0);
    accumulateChannel(slot, CH_NORMAL_POS_Y, n.y > 0.0 ? n2.y : 0.0);
    accumulateChannel(slot, CH_NORMAL_NEG_Y, n.y < 0.0 ? n2.y : 0.0);
    accumulateChannel(slot, CH_NORMAL_POS_Z, n.z > 0.0 ? n2.z : 0.0);
    accumulateChannel(slot, CH_NORMAL_NEG_Z, n.z < 0.0 ? n2.z : 0.0);
    accumulateChannel(slot, CH_FIRST_X, n.x);
    accumulateChannel(slot, CH_FIRST_Y, n.y);
    accumulateChannel(slot, CH_FIRST_Z, n.z);
    return slot1;
}
