// The one cone tracer of dvsgi (paper section VIII), used by the voxel bounce
// and the per-pixel gather. Needs `grid` (VoxelGrid) and `directional`
// (sampler3D: the six volumes' atlas, shared/voxel_data.h); with CONE_USE_RADIANCE_VOLUME also
// `radianceVolume` (sampler3D), blended in for cone diameters of 1-2 voxels.
// With DVSGI_CLIPMAP it traces clipmap levels instead (vxgi/clipmap.h):
// `clip` (ConeLevels), `directionalAtlas` and `radianceAtlas` (the levels'
// volumes stacked along z), starting at level CONE_FIRST_LEVEL (default 0).

#include "lib/math.glsl"
#ifdef CONE_USE_RADIANCE_VOLUME
#include "lib/voxel_sides.glsl"
#endif

#ifdef DVSGI_CLIPMAP
#ifndef CONE_FIRST_LEVEL
#define CONE_FIRST_LEVEL 0
#endif
VoxelGrid traceGrid(int l) { return clip.level[l]; }
// The levels' volumes lie stacked along z in one atlas each (vxgi/clipmap.h),
// so a level is picked by arithmetic: a switch over one sampler per level ran
// every case on llvmpipe (8x the cost of a fitted grid's trace). z stays
// inside level l's slab (`size` cells deep at this mip) and fades toward the
// empty border within half a cell of its faces, as the sampler's border does
// for a volume of its own.
vec4 atlasSample(sampler3D atlas, int l, vec3 uvw, float size, float lod) {
    float z = uvw.z * size;
    float inside = clamp(min(z + 0.5, size + 0.5 - z), 0.0, 1.0);
    uvw.z = (float(l) * size + clamp(z, 0.5, size - 0.5)) / (size * float(clip.count.x));
    return inside * textureLod(atlas, uvw, lod);
}
vec4 directionalAt(int l, vec3 uvw, float lod) {
    return atlasSample(directionalAtlas, l, uvw, max(float(traceGrid(l).dims.x / 2u) * exp2(-lod), 1.0), lod);
}
#ifdef CONE_USE_RADIANCE_VOLUME
vec4 radianceAt(int l, vec3 uvw) { return atlasSample(radianceAtlas, l, uvw, float(traceGrid(l).dims.x), 0.0); }
// Level l's voxel c (of n per edge, inside the level), unfiltered.
vec4 radianceVoxel(int l, ivec3 c, int n) { return texelFetch(radianceAtlas, ivec3(c.xy, l * n + c.z), 0); }
// The opacity of level l's voxel that holds uvw, unfiltered (0 outside the level).
float radianceOpacityAt(int l, vec3 uvw, float size) {
    ivec3 c = ivec3(floor(uvw * size));
    int n = int(size);
    if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(n)))) return 0.0;
    return radianceVoxel(l, c, n).a;
}
#endif
#else
#define CONE_FIRST_LEVEL 0
VoxelGrid traceGrid(int l) { return grid; }
vec4 directionalAt(int l, vec3 uvw, float lod) { return textureLod(directional, uvw, lod); }
#ifdef CONE_USE_RADIANCE_VOLUME
vec4 radianceAt(int l, vec3 uvw) { return textureLod(radianceVolume, uvw, 0.0); }
// Voxel c (of n per edge, inside the grid), unfiltered.
vec4 radianceVoxel(int l, ivec3 c, int n) { return texelFetch(radianceVolume, c, 0); }
// The opacity of the voxel that holds uvw, unfiltered.
float radianceOpacityAt(int l, vec3 uvw, float size) {
    int n = int(size);
    return radianceVoxel(l, clamp(ivec3(floor(uvw * size)), ivec3(0), ivec3(n - 1)), n).a;
}
#endif
#endif

// One directional volume's contribution at (whole) mip level `lod`, weighted
// by w: optical depth tau and emission tau * L (L = colour / alpha). Across
// the travel axis the hardware interpolates bilinearly in opacity (a cell's
// alpha is the fraction of its columns that are blocked: coverage). Along the
// axis the two cells around the sample are fetched and their optical depths
// interpolated: opacity interpolated between an opaque cell and an empty one
// gives a ramp whose step-corrected transmittance is e^-2, so a cone crossed a
// one-cell wall at every mip level keeping 14 % of its light (closed rooms
// lost light, thin walls leaked; docs/quality.md), while optical depth
// integrates to the cell's own. The depth ramps over the middle DEPTH_RAMP of
// the way between the cell centres: a linear ramp saturates half a cell early
// at an opaque cell, which moved hits (ambient occlusion's distance falloff
// was 2 % off its closed form), and stepping at the cell boundary would band.
// The ramp reaches DEPTH_RAMP / 2 cells past an opaque cell, so cones start
// clear of their surface: the bounce's origin is two voxels off
// (vxgi::bounceCones), the clearance K keeps the rest.
const float DEPTH_RAMP = 0.5;

// Volume `face` at uvw (of that volume) in the atlas, as if it had its own
// image with the sampler's transparent border: x stays inside the volume (the
// filter never reaches into the neighbouring one), and within half a cell of
// its edge the result fades toward the empty border as the filter would have.
vec4 fetchVolume(int l, uint face, vec3 uvw, float size, float lod) {
    float x = uvw.x * size;
    float inside = clamp(min(x + 0.5, size + 0.5 - x), 0.0, 1.0);
    uvw.x = (float(face) * size + clamp(x, 0.5, size - 0.5)) / (size * float(DIRECTIONAL_VOLUMES));
    return inside * directionalAt(l, uvw, lod);
}

// The two cells around uvw along `axis` (of a volume with `size` cells per
// edge): their centres p0, p1, and the returned weight of p1's optical depth.
float cellsAlongAxis(vec3 uvw, int axis, float size, out vec3 p0, out vec3 p1) {
    float x = uvw[axis] * size - 0.5;
    float c = floor(x);
    p0 = uvw;
    p1 = uvw;
    p0[axis] = (c + 0.5) / size;
    p1[axis] = (c + 1.5) / size;
    return clamp((x - c - 0.5) / DEPTH_RAMP + 0.5, 0.0, 1.0);
}

// Adds w times the optical depth tau = -ln(1 - alpha) and emission tau L
// interpolated between two premultiplied cell values (weight f on b).
void addOpticalDepth(vec4 a, vec4 b, float f, float w, inout vec4 acc) {
    float ta = -log(1.0 - min(a.a, 0.9999)), tb = -log(1.0 - min(b.a, 0.9999));
    vec3 ja = a.a > 1e-6 ? a.rgb * (ta / a.a) : vec3(0.0);
    vec3 jb = b.a > 1e-6 ? b.rgb * (tb / b.a) : vec3(0.0);
    acc += w * vec4(mix(ja, jb, f), mix(ta, tb, f));
}

// A premultiplied sample whose opacity stands for a slab of depth 1, as it
// stands for a slab `ratio` times as deep (alpha' = 1 - (1 - alpha)^ratio, the
// colour kept in proportion).
vec4 forDepthRatio(vec4 smp, float ratio) {
    float a = clamp(smp.a, 0.0, 1.0);
    float ac = 1.0 - pow(1.0 - min(a, 0.9999), ratio);
    return vec4(a > 1e-6 ? smp.rgb * (ac / a) : vec3(0.0), ac);
}

// Summed (tau L, tau) back to premultiplied (alpha L, alpha).
vec4 premultiplied(vec4 acc) {
    if (acc.a <= 1e-6) return vec4(0.0);
    float a = 1.0 - exp(-acc.a);
    return vec4(acc.rgb * (a / acc.a), a);
}

void tapDirectional(int l, uint face, int axis, vec3 uvw, float lod, float w, inout vec4 acc) {
    // Cells per edge at this level, from the grid rather than textureSize:
    // lavapipe answers a size query with one lane's level for all lanes.
    float size = max(float(traceGrid(l).dims.x / 2u) * exp2(-lod), 1.0);
    vec3 p0, p1;
    float f = cellsAlongAxis(uvw, axis, size, p0, p1);
    addOpticalDepth(fetchVolume(l, face, p0, size, lod), fetchVolume(l, face, p1, size, lod), f, w, acc);
}

#ifdef CONE_USE_RADIANCE_VOLUME

// A sample finer than directional level 0's cells (footprint `level` < 1 of
// one-voxel cells): the radiance volume (one-voxel cells, the same opacity
// every way) sampled as the directional volumes are, along the axis the cone
// travels most (trilinear opacity across a one-voxel surface is a tent whose
// step-corrected transmittance is about 0.1, so narrow shadow cones saw
// through single-layer occluders: umbra 0.10 instead of 0), blended toward
// the directional sample `directional` as the footprint grows.
// Where any voxel the sample would read is two-sided (lib/voxel_sides.glsl),
// the directional sample alone: its level 0 shows a thin wall's sides by the
// way the cone travels, where the radiance volume's one value per voxel
// cannot (it holds the darker side). All eight voxels count, not only the two
// on the sample's own line along the axis: a sample beside a thin wall's voxel
// mixed its darker side in across the axis, so the ground beside a sunlit thin
// wall saw it dark (docs/quality.md, "A slab across the lattice"). The eight
// are fetched one by one and mixed here (on llvmpipe the gather 4 % dearer than
// two trilinear reads and two marks). And a sample near one thin wall,
// travelling toward it, shows the side facing it: the directional volume of
// the wall's axis alone, where the dir^2-weighted sample mixed in the black
// edge the other two volumes show (3 % more). Only where the radiance counts
// (CONE_NEAR_SIDES, the gather): the lighting pass's cones use the opacity
// alone and keep the cheaper sample below.
// The axis a cone travelling along `dir` travels most.
int majorAxis(vec3 dir) {
    vec3 a = abs(dir);
    return a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
}

// A near sample beside a two-sided voxel, from the directional (tau L, tau)
// `depth` of level 0: its cells are two voxels deep and the caller corrects
// the opacity for a slab as deep as the footprint (2^level voxels), so the
// depth is taken per that depth, or it would count twice.
vec4 nearFromDirectional(vec4 depth, float level) { return premultiplied(depth * exp2(max(level, 0.0) - 1.0)); }

// A near sample from the radiance volume's two cells along the travel axis
// (optical depth ramped by f between them), blended toward the directional
// sample as the footprint grows to two voxels.
vec4 nearFromCells(vec4 c0, vec4 c1, float f, vec4 directional, float level) {
    vec4 acc = vec4(0.0);
    addOpticalDepth(c0, c1, f, 1.0, acc);
    return mix(premultiplied(acc), directional, max(level, 0.0));
}

#ifdef CONE_NEAR_SIDES
vec4 sampleNear(int l, vec3 uvw, vec3 dir, vec4 directional, vec4 taps[4], float level) {
    int axis = majorAxis(dir);
    int u = (axis + 1) % 3, w = (axis + 2) % 3;
    int n = int(traceGrid(l).dims.x);
    vec3 q = uvw * float(n) - 0.5;
    ivec3 c = ivec3(floor(q));
    vec3 fr = q - vec3(c);
    // Voxels outside the grid are empty, as the sampler's border: fetched
    // clamped and weighted 0, with no branch per voxel.
    ivec3 lo = clamp(c, ivec3(0), ivec3(n - 1)), hi = clamp(c + 1, ivec3(0), ivec3(n - 1));
    vec3 in0 = vec3(equal(lo, c)), in1 = vec3(equal(hi, c + 1));
    vec4 cell[2];
    // The marks' range (1 - opacity of marked voxels) and the last marked
    // voxel, kept with selects and decoded once below.
    float markLo = 1.0, markHi = 0.0;
    vec3 wallVoxel = vec3(0.0);
    for (int k = 0; k < 2; ++k) {
        vec4 v[4];
        for (int i = 0; i < 4; ++i) {
            ivec3 p = lo;
            p[axis] = k == 0 ? lo[axis] : hi[axis];
            p[u] = (i & 1) == 0 ? lo[u] : hi[u];
            p[w] = (i >> 1) == 0 ? lo[w] : hi[w];
            float inside = (k == 0 ? in0[axis] : in1[axis]) * ((i & 1) == 0 ? in0[u] : in1[u]) *
                           ((i >> 1) == 0 ? in0[w] : in1[w]);
            v[i] = inside * radianceVoxel(l, p, n);
            bool marked = marksTwoSided(v[i].a);
            markHi = marked ? max(markHi, 1.0 - v[i].a) : markHi;
            markLo = marked ? min(markLo, 1.0 - v[i].a) : markLo;
            wallVoxel = marked ? vec3(p) : wallVoxel;
        }
        cell[k] = mix(mix(v[0], v[1], fr[u]), mix(v[2], v[3], fr[u]), fr[w]);
    }
    if (markHi > 0.0) {
        vec4 depth = taps[3];  // the directional sample's (tau L, tau)
        // One wall's voxels, all two-sided along one axis: show the side facing
        // the sample (a ray from there that reaches the wall meets that side).
        int wallAxis = markLo == markHi ? twoSidedAxis(sideCodeOfOpacity(1.0 - markHi)) : -1;
        // Selected by mask, not by index: indexed by wallAxis, this branch cost
        // the gather about twice as much on llvmpipe.
        vec3 onAxis = vec3(equal(ivec3(0, 1, 2), ivec3(wallAxis)));
        float side = dot(onAxis, q - wallVoxel);
        // The directional sample's own tap of that axis, at full weight:
        // the volume for rays travelling toward the wall from this side.
        if (dot(onAxis, dir) * side < 0.0) depth = onAxis.x * taps[0] + onAxis.y * taps[1] + onAxis.z * taps[2];
        return nearFromDirectional(depth, level);
    }
    // The depth ramp of cellsAlongAxis between the two cells' centres.
    return nearFromCells(cell[0], cell[1], clamp((fr[axis] - 0.5) / DEPTH_RAMP + 0.5, 0.0, 1.0), directional, level);
}
#else
// For opacity alone: the two cells read by the hardware's filter, and the two
// voxels on the sample's line checked for the mark.
vec4 sampleNear(int l, vec3 uvw, vec3 dir, vec4 directional, vec4 taps[4], float level) {
    float size = float(traceGrid(l).dims.x);
    vec3 p0, p1;
    float f = cellsAlongAxis(uvw, majorAxis(dir), size, p0, p1);
    if (marksTwoSided(radianceOpacityAt(l, p0, size)) || marksTwoSided(radianceOpacityAt(l, p1, size)))
        return nearFromDirectional(taps[3], level);
    return nearFromCells(radianceAt(l, p0), radianceAt(l, p1), f, directional, level);
}
#endif
#endif

// The three volumes facing `dir` at one whole level: their weighted optical
// depths add, T = prod T_i^(w_i), and the radiance is the depth-weighted mean.
// Returns premultiplied (alpha L, alpha). The volume for each axis is picked by
// index into the atlas (the -axis volume, or the next one for dir >= 0), so
// only the three facing volumes are fetched, with no branch (llvmpipe runs
// divergent branches both ways).
// `taps` receives each volume's (tau L, tau) unweighted, and their weighted sum.
vec4 sampleFacing(int l, vec3 uvw, vec3 dir, vec3 w, float lod, out vec4 taps[4]) {
    uvec3 face = uvec3(0u, 2u, 4u) + uvec3(greaterThanEqual(dir, vec3(0.0)));
    taps[0] = taps[1] = taps[2] = vec4(0.0);
    tapDirectional(l, face.x, 0, uvw, lod, 1.0, taps[0]);
    tapDirectional(l, face.y, 1, uvw, lod, 1.0, taps[1]);
    tapDirectional(l, face.z, 2, uvw, lod, 1.0, taps[2]);
    taps[3] = w.x * taps[0] + w.y * taps[1] + w.z * taps[2];
    return premultiplied(taps[3]);
}

// Directional sample for a cone marching along unit `dir` at mip `level`: the
// three volumes computed for rays travelling that way, weighted by dir^2 (sum
// 1). Optical depths add, not opacities: a wall is opaque in the volume across
// it and nearly transparent in the two along it, and averaging opacities let
// an oblique cone through it. Returns premultiplied (alpha L, alpha).
// Mip levels are not blended by the hardware, which would mix opacity along
// the axis again (a closed box's bounce fell back from 0.99 to 0.91 of the
// light). With `blendLevels` both whole levels around `level` are sampled and
// mixed as coverage, like the footprint they stand for (narrow specular and
// shadow cones, whose width shows: mixing depths made a rough reflection as
// sharp as a glossy one); without, the level is rounded, at half the cost: a
// diffuse cone's level depends only on its distance, so rounding changes no
// pixel against its neighbours (blending cost the voxel bounce 3x on lavapipe).
// `taps`: the three volumes' (tau L, tau) at the (lower) level, unweighted, and
// their weighted sum (sampleFacing).
vec4 sampleDirectional(int l, vec3 uvw, vec3 dir, float level, bool blendLevels, out vec4 taps[4]) {
    vec3 w = dir * dir;
    if (!blendLevels) return sampleFacing(l, uvw, dir, w, floor(level + 0.5), taps);
    float lod = floor(level), fr = level - lod;
    vec4 s = sampleFacing(l, uvw, dir, w, lod, taps);
    vec4 upper[4];
    return fr > 0.0 ? mix(s, sampleFacing(l, uvw, dir, w, lod + 1.0, upper), fr) : s;
}

#ifdef DVSGI_CLIPMAP
// Voxels of a level next to its window's face over which the next level is
// blended in, so a cone (or a row of pixels) crossing the border sees no jump.
const float CLIP_BLEND_VOXELS = 4.0;

// The level a sample of footprint d (world) at p reads: the finest from
// `first` up whose voxels are no smaller than d / 4 (each level reads its
// radiance volume and directional mips 0-1, cells of 1-4 of its voxels; mip
// 2 would be the next level's mip 1) and whose window holds p at least a
// footprint from its faces (the coarsest: anywhere inside). `blend` is the
// weight of level l + 1 near l's faces. False: p is outside every window.
bool clipLevelAt(vec3 p, float d, int first, out int l, out float blend) {
    int levels = int(clip.count.x);
    l = clamp(int(floor(log2(d / traceGrid(0).originSize.w))) - 1, first, levels - 1);
    blend = 0.0;
    for (; l < levels; ++l) {
        VoxelGrid g = traceGrid(l);
        vec3 v = (p - g.originSize.xyz) / g.originSize.w;
        float n = float(g.dims.x);
        float edge = min(min(min(v.x, v.y), v.z), n - max(max(v.x, v.y), v.z));
        if (l == levels - 1) return edge >= 0.0;
        float margin = edge - max(d / g.originSize.w, 1.0);
        if (margin >= 0.0) {
            blend = clamp(1.0 - margin / CLIP_BLEND_VOXELS, 0.0, 1.0);
            return true;
        }
    }
    return false;
}

// Voxels a surface point keeps from the faces of the level its cones start at.
const float CLIP_SURFACE_MARGIN = 2.0;

// The level a surface point's cones start at: the finest whose window holds
// p CLIP_SURFACE_MARGIN of its voxels inside (offsets and clearance are then
// in its voxels, as a fitted grid of that voxel would have them; starting in a
// finer level that does not hold the surface would sample its own coarse voxel).
// Within CLIP_BLEND_VOXELS of that margin, `blend` weighs the next level's start.
int clipSurfaceLevel(vec3 p, out float blend) {
    int levels = int(clip.count.x);
    blend = 0.0;
    for (int l = 0; l < levels - 1; ++l) {
        VoxelGrid g = traceGrid(l);
        vec3 v = (p - g.originSize.xyz) / g.originSize.w;
        float edge = min(min(min(v.x, v.y), v.z), float(g.dims.x) - max(max(v.x, v.y), v.z));
        float margin = edge - CLIP_SURFACE_MARGIN;
        if (margin >= 0.0) {
            blend = clamp(1.0 - margin / CLIP_BLEND_VOXELS, 0.0, 1.0);
            return l;
        }
    }
    return levels - 1;
}

// The sample of footprint d at p from level l, as the fitted grid samples.
vec4 sampleLevel(int l, vec3 p, vec3 dir, float d, bool blendLevels) {
    VoxelGrid g = traceGrid(l);
    float level = log2(d / g.originSize.w);
    vec3 uvw = (p - g.originSize.xyz) / (g.originSize.w * float(g.dims.x));
    vec4 taps[4];
    vec4 smp = sampleDirectional(l, uvw, dir, clamp(level - 1.0, 0.0, float(g.dims.z) - 1.0), blendLevels, taps);
#ifdef CONE_USE_RADIANCE_VOLUME
    if (level < 1.0) smp = sampleNear(l, uvw, dir, smp, taps, level);
#endif
    return smp;
}
#endif

// Front-to-back accumulation along the cone from `origin` (world) along unit
// `dir`, half-angle tangent `tanHalf`; `origin` lies `originHeight` (world)
// above a surface of normal `n`. Returns premultiplied radiance (rgb,
// W m^-2 sr^-1 as seen from the origin) and accumulated opacity (a).
// params.trace: x step factor beta (step = beta * diameter), y minimum step in
// voxels, z maximum distance in metres, w distance of the first sample in voxels.
// `ao` receives the occlusion weighted by f(r) = 1 / (1 + aoLambda * r), r the
// distance in voxels: occ += (1 - occ) * alpha * f(r) (ambient occlusion).
// `blendLevels`: see sampleDirectional (the diffuse cone sets pass false).
vec4 traceConeAO(vec3 origin, vec3 n, float originHeight, vec3 dir, float tanHalf, ConeParams params, float aoLambda,
                 bool blendLevels, out float ao) {
#ifdef DVSGI_CLIPMAP
    // Distances, steps and the clearance are in voxels of the first level.
    float s = traceGrid(CONE_FIRST_LEVEL).originSize.w;
#else
    float s = grid.originSize.w;
    float extent = s * float(grid.dims.x);
    float maxLevel = float(grid.dims.z) - 1.0;
#endif
    vec4 acc = vec4(0.0);
    ao = 0.0;
    float t = params.trace.w * s;
#ifdef CONE_USE_RADIANCE_VOLUME
    float finest = s;        // the radiance volume's cells
#else
    float finest = 2.0 * s;  // directional level 0's cells
#endif
    for (int i = 0; i < 1024 && t < params.trace.z && acc.a < 0.995; ++i) {
        // Diameter 2 t tan(theta/2), no smaller than the finest cell there is.
        float dCone = max(2.0 * t * tanHalf, finest);
        float d = dCone;
        // Clearance: a sample's trilinear footprint spans about one cell on
        // each side, and blending two mip levels doubles that, so a wide cone
        // would read the cells of the surface it leaves (self-illumination,
        // AO < 1 on an open plane). Keep the cell below the height over that
        // surface (minus its voxel thickness) divided by K. For cones wider
        // than about cos(angle to the normal) / K this holds along the whole
        // cone: it then samples like a narrower cone.
        if (params.surface.x > 0.0) {
            float hs = originHeight + t * dot(dir, n);
            d = clamp((hs - params.surface.y * s) / params.surface.x, finest, d);
        }
#ifdef DVSGI_CLIPMAP
        vec3 p = origin + dir * t;
        int l;
        float blend;
        if (!clipLevelAt(p, d, CONE_FIRST_LEVEL, l, blend)) break;  // outside every level
        vec4 smp = sampleLevel(l, p, dir, d, blendLevels);
        if (blend > 0.0) smp = mix(smp, sampleLevel(l + 1, p, dir, d, blendLevels), blend);
#else
        float level = log2(d / s);
        vec3 uvw = (origin + dir * t - grid.originSize.xyz) / extent;
        // Outside the grid there is nothing: the cone ends there. (A last
        // sample on the boundary, read with clamp-to-edge, once plugged leaks
        // of closed boxes but lit open scenes with their coarse boundary cells:
        // cornell-lights converged 22 % too bright; docs/quality.md.)
        if (any(lessThan(uvw, vec3(0.0))) || any(greaterThan(uvw, vec3(1.0)))) break;
        // Directional level 0 voxels are two voxels wide.
        vec4 taps[4];
        vec4 smp = sampleDirectional(0, uvw, dir, clamp(level - 1.0, 0.0, maxLevel), blendLevels, taps);
#ifdef CONE_USE_RADIANCE_VOLUME
        if (level < 1.0) smp = sampleNear(0, uvw, dir, smp, taps, level);
#endif
#endif
        // Steps follow the cone's diameter but never exceed the sampled cell,
        // so a clamped (finer) footprint does not step over a thin wall.
        float stepLen = max(min(params.trace.x * dCone, d), params.trace.y * s);
        // A sample's opacity stands for a slab one cell thick: rescale it
        // to the step actually taken so results do not depend on beta.
        vec4 stepped = forDepthRatio(smp, stepLen / d);
        float ac = stepped.a;
        vec3 c = stepped.rgb;
        // Each step occludes what still gets through it (the transmittance
        // before it), weighted by its distance: sum_k T_k alpha_k f(r_k).
        ao += (1.0 - acc.a) * ac / (1.0 + aoLambda * t / s);
        acc.rgb += (1.0 - acc.a) * c;
        acc.a += (1.0 - acc.a) * ac;
        t += stepLen;
    }
    return acc;
}

vec4 traceCone(vec3 origin, vec3 n, float originHeight, vec3 dir, float tanHalf, ConeParams params,
               bool blendLevels) {
    float ao;
    return traceConeAO(origin, n, originHeight, dir, tanHalf, params, 0.0, blendLevels, ao);
}

// Cone sets over the hemisphere around n, cosine-weighted and normalized so a
// uniform environment of radiance L gives irradiance pi * L. Returns the
// irradiance (W/m^2) and the mean occlusion in `occlusion`.
const float TAN_30 = 0.57735027;

void coneBasis(vec3 n, out vec3 t, out vec3 b) {
    vec3 up = abs(n.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    t = normalize(cross(up, n));
    b = cross(n, t);
}

// Direction of cone k of the paper's six (0 along n, 1-5 at 60 degrees from
// it, phi = 72 (k - 1) degrees around n from t toward b).
vec3 sixConeDirection(vec3 n, vec3 t, vec3 b, int k) {
    if (k == 0) return n;
    float phi = TWO_PI * float(k - 1) / 5.0;
    return normalize(0.5 * n + 0.8660254 * (cos(phi) * t + sin(phi) * b));
}

// The paper's six 60-degree cones: one along n, five at 60 degrees from it,
// the set turned about n by `turn` (a fraction of a full turn).
// `occlusion` is the cones' opacity weighted by f(r) = 1 / (1 + aoLambda r);
// with aoLambda = 0 it is their plain opacity (the voxel bounce).
vec3 gatherIrradiance6(vec3 origin, vec3 n, float originHeight, ConeParams params, float aoLambda, float turn,
                       out float occlusion) {
    vec3 t, b;
    coneBasis(n, t, b);
    if (turn != 0.0) {
        float a = TWO_PI * turn;
        t = cos(a) * t + sin(a) * b;
        b = cross(n, t);
    }
    float ao;
#ifdef DVSGI_SINGLE_CONE
    // Diagnostics (scripts/cone-check.sh): the irradiance as if cone k alone
    // covered the hemisphere, pi times its radiance, to compare cone by cone
    // with a traced reference.
    vec4 single = traceConeAO(origin, n, originHeight, sixConeDirection(n, t, b, DVSGI_SINGLE_CONE), TAN_30, params,
                              aoLambda, false, ao);
    occlusion = ao;
    return PI * single.rgb;
#endif
    // Weights pi * cos(theta_i) / sum cos(theta_j): 1 + 5 * 0.5 = 3.5.
    const float wCenter = PI / 3.5, wSide = PI * 0.5 / 3.5;
    vec3 E = vec3(0.0);
    occlusion = 0.0;
    for (int k = 0; k < 6; ++k) {
        vec4 c = traceConeAO(origin, n, originHeight, sixConeDirection(n, t, b, k), TAN_30, params, aoLambda, false, ao);
        float w = k == 0 ? wCenter : wSide;
        E += w * c.rgb;
        occlusion += w * ao;
    }
    occlusion /= PI;
    return E;
}
