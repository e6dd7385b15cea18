#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_data.h"
#include "shared/shadow_pass.h"
#include "shared/inject_pass.h"
#include "shared/voxel_data.h"
#include "shared/voxel_list_pass.h"
#include "shared/bounce_pass.h"

// Direct light per occupied voxel (paper section VI), visible or not: Lambert
// radiance rho/pi * E * attenuation * visibility for every light, plus the
// voxel's emitted radiance. Writes it to the voxel's slot of the direct light
// (kept for the bounces; alpha 1 + its side code) and to the radiance volume,
// alpha = opacity (1 for occupied voxels, twoSidedOpacity(code) for those with
// another side code). A two-sided voxel
// (lib/voxel_sides.glsl) is also lit side by side into its side light, and
// its radiance texel shows its darker side (black if it is two-sided along
// several axes): the texel is one value for every way a cone reads it, and
// a sunlit side shown there glowed through the wall to pixels beside it
// (cones read the sides themselves where they can: lib/cone_trace.glsl).
// One invocation per occupied voxel (an entry of the list); empty voxels keep
// the zero that clears left.
layout(local_size_x = VOXEL_LIST_GROUP) in;

layout(set = 0, binding = BIND_INJECT_GRID) uniform Grid { VoxelGrid grid; };
layout(set = 0, binding = BIND_INJECT_ACCUM, r32f) uniform readonly image3D accum;
layout(set = 0, binding = BIND_INJECT_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = BIND_INJECT_SHADOW_VIEWS, std430) readonly buffer Views { GpuShadowView shadowViews[]; };
layout(set = 0, binding = BIND_INJECT_SHADOW_MAP) uniform sampler2DArray shadowMap;
layout(set = 0, binding = BIND_INJECT_SHADOW_GRADIENT) uniform sampler2DArray shadowGradient;
layout(set = 0, binding = BIND_INJECT_DIRECT, rgba16f) uniform writeonly image3D outDirect;
layout(set = 0, binding = BIND_INJECT_OUT_RADIANCE, rgba16f) uniform writeonly image3D outRadiance;
layout(set = 0, binding = BIND_INJECT_SIDES, rgba32ui) uniform uimage3D sides;
VOXEL_INDEX_BLOCK(BIND_INJECT_INDEX, readonly);
VOXEL_LIST_BLOCK(BIND_INJECT_LIST, readonly);
VOXEL_EXTENTS_BLOCK(BIND_INJECT_EXTENTS, readonly);
layout(push_constant) uniform Push { VoxelLightPush pc; };
#ifdef DVSGI_RAY_OCCUPANCY
// Built with RAY_OCCUPANCY where this frame's rays' occupancy bits are packed
// before the voxel light (a fitted grid's): voxel shadow rays cross empty
// cells in one step, meeting the same voxels.
layout(set = 0, binding = BIND_INJECT_RAY_OCCUPANCY, std430) readonly buffer RayOccupancy { uint rayOccupancy[]; };
#define VOXEL_TRACE_SKIPS_EMPTY
#endif

#include "lib/math.glsl"
#include "lib/voxel_attributes.glsl"
#include "lib/voxel_sides.glsl"
#include "lib/voxel_index.glsl"
#include "lib/voxel_extents.glsl"
#include "lib/lights.glsl"
#include "lib/shadow_map.glsl"
#ifdef DVSGI_RAY_OCCUPANCY
#include "lib/voxel_occupancy.glsl"
#endif
#include "lib/voxel_trace.glsl"
#include "lib/voxel_list_dispatch.glsl"


// The shadow map is looked up at a point on the surface (Pmap), the voxel
// rays start from Pray, a voxel face or half a voxel out from the centre:
// their first sample lies a voxel along the light, and from a point inside
// the voxel it met the surface's own neighbour under a grazing light.
float visibility(GpuLight light, uint mode, vec3 Pmap, vec3 Pray, vec3 n, vec3 L, float dist) {
    if (mode == OCCLUSION_SHADOW_MAP && pc.flags.w != 0u) return shadowVisibility(light, Pmap, n, pc.params.y);
    if (mode == OCCLUSION_RAYCAST_HARD || mode == OCCLUSION_RAYCAST_SOFT)
        return voxelRayVisibility(Pray, L, dist, mode == OCCLUSION_RAYCAST_SOFT, pc.params.x);
    return 1.0;
}

// Where a voxel's surface facing +axis a (or -a) lies, for its shadow
// lookups: the middle of the box its extents cover, on that box's face on
// that side: for one plane along the axis at most an eighth of a voxel in
// front of it, and never behind a surface the voxel holds. Looked up
// half a voxel off the centre, a floor's voxel was lit from up to a voxel
// above the floor, and every shadow edge moved that height times the tangent
// of the light's angle toward the light: the sun's patch in a room lit
// through a window lay a voxel nearer the window, and the window's wall saw
// it 6-9 % too bright (docs/quality.md, "Where a voxel's light is looked
// up"). lo, hi: the box (extentBox); without extents (the pv voxelizer's)
// it is the voxel, and this is its face.
vec3 surfaceFace(vec3 lo, vec3 hi, int a, bool plus) {
    vec3 q = 0.5 * (lo + hi);
    q[a] = plus ? hi[a] : lo[a];
    return grid.originSize.xyz + q * grid.originSize.w;
}

// The visibility of a voxel's face along axis a on its + or - side (an edge's
// face, a thin wall's side): its shadow map looked up on that side's face of
// the extents' box (lo, hi), its voxel rays from just outside the voxel there.
float faceVisibility(GpuLight light, uint mode, vec3 lo, vec3 hi, vec3 centre, int a, bool plus, vec3 L, float dist) {
    vec3 e = vec3(0.0);
    e[a] = plus ? 1.0 : -1.0;
    return visibility(light, mode, surfaceFace(lo, hi, a, plus), centre + e * (0.5 * grid.originSize.w), e, L, dist);
}

void main() {
    uint entry = listInvocation();
    if (entry >= list.header.counts.x || list.entries[entry] == VOXEL_LIST_FREE) return;
    ivec3 v = listVoxel(list.entries[entry]);
    uint slot = entry;
    vec3 albedo = voxelAlbedo(slot);
    vec3 pos, neg;
    voxelNormalWeights(slot, pos, neg);
    vec3 n = voxelNormal(slot);
    // --edge-voxels faces (keep.y, with Lambert only): the share of the voxel
    // that is one plane is lit with Lambert, the rest as faces along the axes.
    bool edges = pc.keep.y != 0u;
    float planeW = edges ? voxelPlaneShare(slot, pos, neg) : 1.0;
    float s = grid.originSize.w;
    vec3 centre = grid.originSize.xyz + (vec3(v) + 0.5) * s;
    // Shadows are looked up on the surface of a floor's or a wall's voxel
    // (surfaceFace), elsewhere at the voxel centre pushed half a voxel along
    // its normal (the mean normal of an edge or a tilted staircase is no plane
    // the extents place). The light's falloff is taken at the centre: over
    // where planes cross voxels the surface lies there on average; taken half
    // a voxel nearer a point light, cornell-lights' first two bounces came out
    // 1.0 % and 1.2 % too bright at 64^3 (docs/quality.md).
    vec3 boxLo, boxHi;
    extentBox(v, voxelExtents[slot], boxLo, boxHi);
    int nAxis = largestAxis(abs(n));
    vec3 P = centre + n * (0.5 * s);
    vec3 onSurface = alongAnAxis(n) ? surfaceFace(boxLo, boxHi, nAxis, n[nAxis] > 0.0) : P;
    // A two-sided voxel's sides (+axis, -axis) are lit as faces with those
    // normals, each looked up on its side's face of the extents' box (voxel
    // raycasts: from just outside the voxel on that side): a thin wall's
    // shadowed face stays dark however the wall's sunlit face is weighted.
    uint code = sideCode(pos, neg);
    int axis = twoSidedAxis(code);
    vec3 sideN[2] = vec3[2](vec3(0.0), vec3(0.0));
    if (axis >= 0) {
        sideN[0][axis] = 1.0;
        sideN[1][axis] = -1.0;
    }

    // Emitters lit explicitly (as LIGHT_AREA patches) keep their emission out
    // of the radiance that cones gather, or it would be counted twice.
    vec3 radiance = pc.params.z > 0.5 ? voxelEmission(slot) : vec3(0.0);
    vec3 side[2] = vec3[2](radiance, radiance);
    // An edge or corner voxel also keeps each axis face's light apart, for
    // rays to see the faces that turn toward them (lib/voxel_rays.glsl).
    bool faces = edges && showsFaces(pos, neg, planeW);
    // An edge or corner of faces along the axes, in the default voxel light
    // (Lambert, --edge-voxels whole): lit face by face, each face weighted by
    // its share of the fragments, and shown as the lesser of that and Lambert
    // with the mean normal, light by light. Where both faces face the light
    // (a room's inside corner) the faces' mean is the surfaces' light; the
    // mean normal gave up to sqrt(2) of it, and cornell-lights after 32
    // bounces came out above its reference. Where only one does (a sill's
    // edge: its sunlit top, its wall's face turned away) a voxel shown the
    // same from every side cannot be right from both; it keeps the lower, as
    // a two-sided voxel shows its darker side: lit by their faces alone, such
    // edges at its window made a room lit through it 2.4 % brighter at 128^3
    // (docs/quality.md, "Edge voxels of axis faces").
    bool axisFaces = !edges && pc.flags.y == 0u && code == SIDE_ONE &&
                     voxelPlaneShare(slot, pos, neg) < AXIS_FACES_BELOW_PLANE_SHARE;
    vec3 face[3] = vec3[3](radiance, radiance, radiance);
    vec3 faceSign = mix(vec3(-1.0), vec3(1.0), greaterThanEqual(pos, neg));
    for (uint i = 0u; i < pc.flags.x; ++i) {
        GpuLight light = lights[i];
        vec3 L;
        float dist;
        vec3 E = lightIrradiance(light, centre, L, dist);
        if (all(equal(E, vec3(0.0)))) continue;
        uint mode = pc.flags.z != OCCLUSION_PER_LIGHT ? pc.flags.z : light.shadow.z;
        bool area = uint(light.position.w) == LIGHT_AREA;
        // Patches have no shadow maps; their rays stop short of the emitter's own voxels.
        if (area && mode == OCCLUSION_SHADOW_MAP) mode = OCCLUSION_RAYCAST_HARD;
        if (area) dist -= 2.0 * s / max(abs(dot(light.direction.xyz, L)), 0.2);
        float cosN = max(dot(n, L), 0.0);
        if (axisFaces) {
            float byNormal = cosN > 0.0 ? cosN * visibility(light, mode, onSurface, P, n, L, dist) : 0.0;
            // The lesser is 0 where the mean normal is turned away or shadowed:
            // the faces' lookups are spent only where they can matter.
            float byFaces = 0.0;
            for (int a = 0; a < 3 && byNormal > 0.0; ++a) {
                float w = L[a] > 0.0 ? pos[a] : neg[a];
                if (w <= 0.0 || L[a] == 0.0) continue;
                byFaces += w * abs(L[a]) * faceVisibility(light, mode, boxLo, boxHi, centre, a, L[a] > 0.0, L, dist);
            }
            radiance += albedo / PI * E * min(byFaces, byNormal);
        } else if (!edges) {
            // Eq. 5 generalized to signed weights: sum over axes of the weight of
            // the normals facing the light along that axis times the cosine there.
            // For a single normal it is exactly W_x D_x + W_y D_y + W_z D_z.
            float att = pc.flags.y != 0u ? dot(pos, max(L, 0.0)) + dot(neg, max(-L, 0.0)) : cosN;
            if (att > 0.0) radiance += albedo / PI * E * att * visibility(light, mode, onSurface, P, n, L, dist);
        } else {
            // A block's edge voxel holds a sunlit face and a shadowed one: lit
            // with their mean normal, both were lit alike. Each face is lit
            // on its side's face of the extents' box (voxel raycasts: from
            // just outside the voxel on that side), weighted by its share of
            // the normals (docs/quality.md, "Surfaces' extent inside their voxels").
            vec3 planeLight = planeW * cosN > 0.0
                                  ? albedo / PI * E * (planeW * cosN) * visibility(light, mode, onSurface, P, n, L, dist)
                                  : vec3(0.0);
            radiance += planeLight;
            for (int a = 0; a < 3; ++a) {
                if (faces) face[a] += planeLight;
                float w = L[a] > 0.0 ? pos[a] : neg[a];
                bool ownFace = faces && faceSign[a] * L[a] > 0.0;
                float cosine = abs(L[a]);
                if (planeW >= 1.0 || cosine <= 0.0 || (w <= 0.0 && !ownFace)) continue;
                vec3 faceLight = (1.0 - planeW) * albedo / PI * E * cosine *
                                 faceVisibility(light, mode, boxLo, boxHi, centre, a, L[a] > 0.0, L, dist);
                radiance += w * faceLight;
                if (ownFace) face[a] += faceLight;
            }
        }
        if (axis < 0) continue;
        for (int k = 0; k < 2; ++k) {
            float cosine = dot(sideN[k], L);
            if (cosine > 0.0)
                side[k] += albedo / PI * E * cosine * faceVisibility(light, mode, boxLo, boxHi, centre, axis, k == 0, L, dist);
        }
    }
    imageStore(outDirect, slotTexel(slot, 0u), vec4(radiance, sideCodeAlpha(code)));
    vec3 shown = code == SIDE_ONE ? radiance : (axis >= 0 ? min(side[0], side[1]) : vec3(0.0));
    // Static voxels keep the direct + reflected light the last bounce left for
    // a feedback frame's rays; the bounce then writes this frame's. Dynamic
    // ones were cleared, and show where they are now.
    if (pc.keep.x == 0u || entry >= list.header.counts.y) imageStore(outRadiance, v, vec4(shown, twoSidedOpacity(code)));
    if (faces) {
        imageStore(sides, slotTexel(slot, 0u),
                   uvec4(packRgb9e5(face[0]), packRgb9e5(face[1]), packRgb9e5(face[2]), packRgb9e5(radiance)));
        return;
    }
    if (axis < 0) return;
    // The reflected light stays for a feedback frame's bounce to blend with;
    // otherwise the bounces start from none.
    ivec3 texel = slotTexel(slot, 0u);
    uvec2 reflected = pc.params.w > 0.5 ? imageLoad(sides, texel).zw : uvec2(0u);
    imageStore(sides, texel, uvec4(packRgb9e5(side[0]), packRgb9e5(side[1]), reflected));
}
