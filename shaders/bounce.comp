#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/bounce_pass.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"

// One bounce per occupied voxel (paper section IX): the irradiance from six
// cones over the voxel's normal hemisphere, traced through the filtered
// directional volumes of the radiance so far, times albedo / pi, added to the
// voxel's direct light + emission. Repeating it (re-filtering between) gives
// L_direct + T L_direct + ... ; reading the previous frame's volumes instead
// (feedback) adds one bounce per frame at the cost of one. A two-sided voxel
// (lib/voxel_sides.glsl) gathers over the hemisphere of the side its weights
// favour with the six cones and over the other's with one wide cone; both go
// to its side light, and its radiance texel shows the darker side.
// Built with RAY_TRACE (--bounce-trace rays), the first of two dispatches:
// each voxel's rays through the radiance volume (lib/voxel_rays.glsl), their
// light kept per slot; built with TRACED, the second: as below, with that
// light instead of the cones'.
// Built with RAY_NORMALS, the dispatch before the rays: each voxel's mean
// normal, packed per slot for the rays to read, with (pc.flags.x = 1,
// --edge-voxels faces) whether it shows its faces and that its extents
// apply, and its cells' occupancy bits (the buffer cleared before).
// One invocation per occupied voxel (an entry of the list, which is its slot).
layout(local_size_x = VOXEL_LIST_GROUP) in;

#ifdef DVSGI_CLIPMAP
// One clipmap level's voxels; cones trace every level from theirs up.
layout(set = 0, binding = BIND_BOUNCE_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_CONE_GRID) uniform Levels { ConeLevels clip; };
layout(set = 0, binding = BIND_CONE_DIRECTIONAL) uniform sampler3D directionalAtlas;
layout(set = 0, binding = BIND_BOUNCE_LEVELS_BEFORE) uniform sampler3D levelsBefore;
#define CONE_FIRST_LEVEL int(pc.flags.y)
#else
layout(set = 0, binding = BIND_CONE_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_CONE_DIRECTIONAL) uniform sampler3D directional;
#endif
layout(set = 0, binding = BIND_BOUNCE_ACCUM, r32f) uniform readonly image3D accum;
layout(set = 0, binding = BIND_BOUNCE_DIRECT, rgba16f) uniform readonly image3D direct;
layout(set = 0, binding = BIND_BOUNCE_OUT, rgba16f) uniform image3D outRadiance;
layout(set = 0, binding = BIND_BOUNCE_STATS, std430) writeonly buffer Stats { float stats[]; };
layout(set = 0, binding = BIND_BOUNCE_HISTORY, rgba32ui) uniform uimage3D history;
layout(set = 0, binding = BIND_BOUNCE_SIDES, rgba32ui) uniform uimage3D sides;
VOXEL_LIST_BLOCK(BIND_BOUNCE_LIST, readonly);
#if defined(DVSGI_RAY_TRACE) || defined(DVSGI_TRACED)
layout(set = 0, binding = BIND_BOUNCE_TRACED, rg32ui) uniform uimage3D traced;
#endif
#if defined(DVSGI_RAY_TRACE) || defined(DVSGI_RAY_NORMALS)
layout(set = 0, binding = BIND_BOUNCE_RAY_NORMALS, r32ui) uniform uimage3D rayNormals;
layout(set = 0, binding = BIND_BOUNCE_RAY_OCCUPANCY, std430) buffer RayOccupancy { uint rayOccupancy[]; };
VOXEL_INDEX_BLOCK(BIND_BOUNCE_INDEX, readonly);
#endif
#if defined(DVSGI_RAY_TRACE) || defined(DVSGI_RAY_NORMALS)
VOXEL_EXTENTS_BLOCK(BIND_BOUNCE_EXTENTS, readonly);
#endif
layout(push_constant) uniform Push { BouncePush pc; };

#include "lib/math.glsl"
#include "lib/voxel_attributes.glsl"
#include "lib/voxel_sides.glsl"
#include "lib/voxel_window.glsl"
#include "lib/cone_trace.glsl"
#include "lib/voxel_list_dispatch.glsl"
#if defined(DVSGI_RAY_TRACE) || defined(DVSGI_RAY_NORMALS)
#include "lib/voxel_index.glsl"
#include "lib/voxel_rays.glsl"
#endif

const uint GROUP_SIZE = VOXEL_LIST_GROUP;
shared vec2 partial[GROUP_SIZE];

// Feedback frames (--voxel-temporal-alpha): the reflected (bounced) light
// moves a fraction alpha of the way from what the same voxel reflected after
// last frame's bounce, so indirect light that changes from frame to frame (a
// moving object's surroundings) changes smoothly; direct light and emission
// are never delayed. The history is kept per slot with the world voxel it
// belongs to (grid voxel + the grid's corner in whole voxels, modulo 1024 per
// axis: the same across a clipmap scroll, unlike the toroidal list entry), so
// a slot that held another voxel last frame, or was not bounced then, or any
// slot while the host holds the history back (after a change of lights,
// static geometry or settings), takes the new value as it is.
// A two-sided voxel's side light keeps its own last reflected light; its
// other side blends with it where the slot's history blends and the voxel had
// the same sides then (`sideTag`: 1 + 2 axis + the favoured side, 0 for a
// one-sided voxel, kept in the history's spare half).
vec3 blendWithHistory(ivec3 v, uint slot, vec3 value, float sideTag, out bool sidesBlend) {
    ivec3 corner = ivec3(round(grid.originSize.xyz / grid.originSize.w));
    uint key = packVoxel((v + corner) & ivec3((1 << VOXEL_LIST_COORD_BITS) - 1));
    ivec3 texel = slotTexel(slot, 0u);
    uvec4 h = imageLoad(history, texel);
    bool same = h.z == key && h.w == pc.blend.y;
    sidesBlend = same && unpackHalf2x16(h.y).y == sideTag;
    if (same) {
        vec3 before = vec3(unpackHalf2x16(h.x), unpackHalf2x16(h.y).x);
        value = before + uintBitsToFloat(pc.blend.z) * (value - before);
    }
    imageStore(history, texel, uvec4(packHalf2x16(value.rg), packHalf2x16(vec2(value.b, sideTag)), key, pc.blend.x));
    return value;
}

// The normal the voxel's bounce gathers about: for a two-sided voxel the side
// its weights favour (`strong` 1: -axis), whose six cones gather there.
vec3 bounceNormal(uint slot, uint code, out int axis, out int strong) {
    vec3 pos, neg;
    voxelNormalWeights(slot, pos, neg);
    vec3 n = voxelNormal(slot);
    if (dot(n, n) < 0.5) {  // opposite faces cancelled: use the strongest weight's axis
        vec3 m = max(pos, neg);
        int a = largestAxis(m);
        n = vec3(0.0);
        n[a] = pos[a] >= neg[a] ? 1.0 : -1.0;
    }
    axis = twoSidedAxis(code);
    int a = max(axis, 0);
    strong = axis >= 0 && pos[a] < neg[a] ? 1 : 0;
    if (axis >= 0) {
        n = vec3(0.0);
        n[a] = strong == 0 ? 1.0 : -1.0;
    }
    return n;
}

#ifdef DVSGI_RAY_NORMALS
void main() {
    uint entry = listInvocation();
    if (entry >= list.header.counts.x || list.entries[entry] == VOXEL_LIST_FREE) return;
    bool edges = pc.flags.x != 0u;
    uint word = packRayNormal(voxelNormal(entry)) | (edges ? RAY_NORMAL_EXTENTS_BIT : 0u) |
                (edges && voxelShowsFaces(entry) ? RAY_NORMAL_FACES_BIT : 0u);
    imageStore(rayNormals, slotTexel(entry, 0u), uvec4(word, 0u, 0u, 0u));
    ivec3 v = listVoxel(list.entries[entry]);
    for (uint level = 0u; level < RAY_OCCUPANCY_LEVELS; ++level) {
        uint bit = rayOccupancyBit(v, level);
        atomicOr(rayOccupancy[rayOccupancyOffset(grid.dims.x, level) + bit / 32u], 1u << (bit % 32u));
    }
}
#elif defined(DVSGI_RAY_TRACE)
void main() {
    uint entry = listInvocation();
    if (entry >= list.header.counts.x || list.entries[entry] == VOXEL_LIST_FREE) return;
    ivec3 v = listVoxel(list.entries[entry]);
    uint code = sideCodeOf(imageLoad(direct, slotTexel(entry, 0u)));
    int axis, strong;
    vec3 n = bounceNormal(entry, code, axis, strong);
    vec3 albedo = voxelAlbedo(entry);
    // The same rays every bounce and frame: a static scene converges to one
    // light, with no noise from frame to frame.
    uint seed = raySeed(v);
    vec3 other;
    vec3 reflected = albedo * voxelRaysCosine(v, n, pc.flags.w, seed,
                                              axis >= 0 ? max(pc.flags.w / 4u, 4u) : 0u, rayHash(seed), pc.flags.z != 0u,
                                              other);
    other *= albedo;
    // A one-sided voxel's light as half floats: in RGB9E5 a bounce's increment
    // fell under the step in a bright closed room and the series stalled 1 %
    // short. A two-sided voxel's two sides as RGB9E5, as its side light keeps them.
    uvec2 packed = axis >= 0 ? uvec2(packRgb9e5(reflected), packRgb9e5(other))
                             : uvec2(packHalf2x16(reflected.rg), packHalf2x16(vec2(reflected.b, 0.0)));
    imageStore(traced, slotTexel(entry, 0u), uvec4(packed, 0u, 0u));
}
#else
// `sideChange`: for a two-sided voxel, the convergence statistics of both
// sides (summed |luminance change| of direct + reflected, and the reflected
// luminance after), since its radiance texel shows only the darker one; x < 0
// otherwise. `reflectedLum`: a one-sided voxel's reflected luminance.
vec4 bounced(ivec3 v, uint slot, out vec2 sideChange, out float reflectedLum) {
    sideChange = vec2(-1.0);
    reflectedLum = 0.0;
    vec4 d = imageLoad(direct, slotTexel(slot, 0u));
    uint code = sideCodeOf(d);
    int axis, strong;
    vec3 n = bounceNormal(slot, code, axis, strong);
    bool twoSided = axis >= 0;
#ifdef DVSGI_TRACED
    // The rays of the pass before (DVSGI_RAY_TRACE) gathered it.
    uvec2 tr = imageLoad(traced, slotTexel(slot, 0u)).xy;
    vec3 reflected = twoSided ? unpackRgb9e5(tr.x) : vec3(unpackHalf2x16(tr.x), unpackHalf2x16(tr.y).x);
    vec3 other = twoSided ? unpackRgb9e5(tr.y) : vec3(0.0);
#else
    vec3 albedo = voxelAlbedo(slot);
    float s = grid.originSize.w;
    // Start off the surface (two voxels: vxgi::bounceCones) so the cones do not gather the voxel itself.
    vec3 origin = grid.originSize.xyz + (vec3(v) + 0.5 + n * pc.cone.surface.z) * s;
    float occlusion;
    vec3 reflected = albedo / PI * gatherIrradiance6(origin, n, s * pc.cone.surface.z, pc.cone, 0.0, 0.0, occlusion);
    // The other side of a two-sided voxel gathers with one cone of 60 degrees
    // half-angle: six cones cost the bounce 40 % more on Sponza, where many
    // voxels hold thin geometry.
    vec3 other = vec3(0.0);
    if (twoSided) {
        vec3 m = -n;
        vec3 o = grid.originSize.xyz + (vec3(v) + 0.5 + m * pc.cone.surface.z) * s;
        other = albedo * traceCone(o, m, s * pc.cone.surface.z, m, 1.7320508, pc.cone, false).rgb;
    }
#endif
    bool blended = false;
    vec3 shown = d.rgb;
    float sideTag = twoSided ? float(1 + 2 * axis + strong) : 0.0;
    if (pc.blend.x != 0u) reflected = blendWithHistory(v, slot, reflected, sideTag, blended);
    if (twoSided) {
        ivec3 texel = slotTexel(slot, 0u);
        uvec4 t = imageLoad(sides, texel);
        if (blended) {
            vec3 before = unpackRgb9e5(strong == 0 ? t.w : t.z);
            other = before + uintBitsToFloat(pc.blend.z) * (other - before);
        }
        uint packed0 = packRgb9e5(strong == 0 ? reflected : other);
        uint packed1 = packRgb9e5(strong == 0 ? other : reflected);
        imageStore(sides, texel, uvec4(t.xy, packed0, packed1));
        // As stored (RGB9E5), so that a side that no longer changes counts no change.
        vec3 side0 = unpackRgb9e5(packed0), side1 = unpackRgb9e5(packed1);
        vec3 lit0 = unpackRgb9e5(t.x), lit1 = unpackRgb9e5(t.y);
        // The radiance texel shows the darker side, as inject.comp writes it.
        shown = min(lit0 + side0, lit1 + side1);
        float after0 = luminance(lit0 + side0), after1 = luminance(lit1 + side1);
        sideChange = vec2(abs(after0 - luminance(lit0 + unpackRgb9e5(t.z))) +
                              abs(after1 - luminance(lit1 + unpackRgb9e5(t.w))),
                          luminance(side0) + luminance(side1));
    } else if (code == SIDE_ONE) {
        shown += reflected;
        reflectedLum = luminance(reflected);
    } else {
        shown = vec3(0.0);
    }
    return vec4(shown, twoSidedOpacity(code));
}

void main() {
    uint entry = listInvocation();
    vec2 change = vec2(0.0);
    if (entry < list.header.counts.x && list.entries[entry] != VOXEL_LIST_FREE) {
        ivec3 v = listVoxel(list.entries[entry]);
        vec2 sideChange;
        float reflectedLum;
        vec4 r = bounced(v, entry, sideChange, reflectedLum);
        // A one-sided voxel's change is taken as stored (half floats; an
        // invocation reads its own write back), so that light that no longer
        // changes counts no change: the sum of direct and reflected light
        // rounded afresh each bounce kept the change near 2e-4 of the voxels'
        // light in a lit room. A two-sided voxel's sides measured theirs.
        bool measureStored = pc.flags.x != 0u && sideChange.x < 0.0 && r.a > 0.0;
        vec3 old = vec3(0.0);
#ifdef DVSGI_CLIPMAP
        if (measureStored) old = texelFetch(levelsBefore, ivec3(v.xy, CONE_FIRST_LEVEL * int(grid.dims.x) + v.z), 0).rgb;
#else
        if (measureStored) old = imageLoad(outRadiance, v).rgb;
#endif
        imageStore(outRadiance, v, r);
        if (pc.flags.x != 0u && sideChange.x >= 0.0)
            change = sideChange;
        else if (measureStored)
            change = vec2(abs(luminance(imageLoad(outRadiance, v).rgb) - luminance(old)), reflectedLum);
    }
    if (pc.flags.x == 0u) return;
    // Tree reduction of the workgroup's sums (all invocations reach the barriers).
    uint i = gl_LocalInvocationIndex;
    partial[i] = change;
    barrier();
    for (uint stride = GROUP_SIZE / 2u; stride > 0u; stride /= 2u) {
        if (i < stride) partial[i] += partial[i + stride];
        barrier();
    }
    if (i == 0u) {
        uint group = listGroupIndex();
        stats[group * BOUNCE_STATS_FLOATS] = partial[0].x;
        stats[group * BOUNCE_STATS_FLOATS + 1u] = partial[0].y;
    }
}
#endif
