// The one cone tracer of dvsgi (paper section VIII), used by the voxel bounce
// and the per-pixel gather. Needs `grid` (VoxelGrid) and `directional[6]`
// (sampler3D, order -X +X -Y +Y -Z +Z); with CONE_USE_RADIANCE_VOLUME also
// `radianceVolume` (sampler3D), blended in for cone diameters of 1-2 voxels.

#include "lib/math.glsl"

// Directional sample for a cone marching along unit `dir`: the three volumes
// computed for rays travelling that way, weighted by dir^2 (sum 1). All six are
// fetched and weighted (zero for the three facing away) so the sampling stays
// branch-free, which is faster on lavapipe than picking volumes by branches.
// Opacity combines as transmittance, T = prod T_i^(w_i), not as the weighted
// mean: a wall is opaque in the volume across it and nearly transparent in the
// two along it, and averaging let an oblique cone through it (light leaked out
// of closed rooms, increasingly at finer grids). Colour is the weighted
// premultiplied colour rescaled to that opacity.
vec4 sampleDirectional(vec3 uvw, vec3 dir, float level) {
    vec3 w = dir * dir;
    vec3 neg = w * vec3(lessThan(dir, vec3(0.0)));
    vec3 pos = w - neg;
    vec4 s0 = textureLod(directional[0], uvw, level), s1 = textureLod(directional[1], uvw, level);
    vec4 s2 = textureLod(directional[2], uvw, level), s3 = textureLod(directional[3], uvw, level);
    vec4 s4 = textureLod(directional[4], uvw, level), s5 = textureLod(directional[5], uvw, level);
    vec4 mean = neg.x * s0 + pos.x * s1 + neg.y * s2 + pos.y * s3 + neg.z * s4 + pos.z * s5;
    float logT = neg.x * log(max(1.0 - s0.a, 1e-6)) + pos.x * log(max(1.0 - s1.a, 1e-6)) +
                 neg.y * log(max(1.0 - s2.a, 1e-6)) + pos.y * log(max(1.0 - s3.a, 1e-6)) +
                 neg.z * log(max(1.0 - s4.a, 1e-6)) + pos.z * log(max(1.0 - s5.a, 1e-6));
    float a = 1.0 - exp(logT);
    return mean.a > 1e-6 ? vec4(mean.rgb * (a / mean.a), a) : vec4(0.0);
}

// Front-to-back accumulation along the cone from `origin` (world) along unit
// `dir`, half-angle tangent `tanHalf`; `origin` lies `originHeight` (world)
// above a surface of normal `n`. Returns premultiplied radiance (rgb,
// W m^-2 sr^-1 as seen from the origin) and accumulated opacity (a).
// params.trace: x step factor beta (step = beta * diameter), y minimum step in
// voxels, z maximum distance in metres, w distance of the first sample in voxels.
// `ao` receives the occlusion weighted by f(r) = 1 / (1 + aoLambda * r), r the
// distance in voxels: occ += (1 - occ) * alpha * f(r) (ambient occlusion).
vec4 traceConeAO(vec3 origin, vec3 n, float originHeight, vec3 dir, float tanHalf, ConeParams params, float aoLambda, out float ao) {
    float s = grid.originSize.w;
    float extent = s * float(grid.dims.x);
    float maxLevel = float(grid.dims.z) - 1.0;
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
        float level = log2(d / s);
        vec3 uvw = (origin + dir * t - grid.originSize.xyz) / extent;
        // Outside the grid there is nothing: the cone ends there. (A last
        // sample on the boundary, read with clamp-to-edge, once plugged leaks
        // of closed boxes but lit open scenes with their coarse boundary cells:
        // cornell-lights converged 22 % too bright; docs/quality.md.)
        if (any(lessThan(uvw, vec3(0.0))) || any(greaterThan(uvw, vec3(1.0)))) break;
        // Directional level 0 voxels are two voxels wide.
        vec4 smp = sampleDirectional(uvw, dir, clamp(level - 1.0, 0.0, maxLevel));
#ifdef CONE_USE_RADIANCE_VOLUME
        if (level < 1.0) smp = mix(textureLod(radianceVolume, uvw, 0.0), smp, level);
#endif
        // Steps follow the cone's diameter but never exceed the sampled cell,
        // so a clamped (finer) footprint does not step over a thin wall.
        float stepLen = max(min(params.trace.x * dCone, d), params.trace.y * s);
        // A sample's opacity stands for a slab one cell thick: rescale it
        // to the step actually taken so results do not depend on beta.
        float a = clamp(smp.a, 0.0, 1.0);
        float ac = 1.0 - pow(1.0 - min(a, 0.9999), stepLen / d);
        vec3 c = a > 1e-6 ? smp.rgb * (ac / a) : vec3(0.0);
        // Each step occludes what still gets through it (the transmittance
        // before it), weighted by its distance: sum_k T_k alpha_k f(r_k).
        ao += (1.0 - acc.a) * ac / (1.0 + aoLambda * t / s);
        acc.rgb += (1.0 - acc.a) * c;
        acc.a += (1.0 - acc.a) * ac;
        t += stepLen;
    }
    return acc;
}

vec4 traceCone(vec3 origin, vec3 n, float originHeight, vec3 dir, float tanHalf, ConeParams params) {
    float ao;
    return traceConeAO(origin, n, originHeight, dir, tanHalf, params, 0.0, ao);
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

// The paper's six 60-degree cones: one along n, five at 60 degrees from it.
// `occlusion` is the cones' opacity weighted by f(r) = 1 / (1 + aoLambda r);
// with aoLambda = 0 it is their plain opacity (the voxel bounce).
vec3 gatherIrradiance6(vec3 origin, vec3 n, float originHeight, ConeParams params, float aoLambda,
                       out float occlusion) {
    vec3 t, b;
    coneBasis(n, t, b);
    const float sin60 = 0.8660254, cos60 = 0.5;
    // Weights pi * cos(theta_i) / sum cos(theta_j): 1 + 5 * 0.5 = 3.5.
    const float wCenter = PI / 3.5, wSide = PI * 0.5 / 3.5;
    float ao;
    vec4 c = traceConeAO(origin, n, originHeight, n, TAN_30, params, aoLambda, ao);
    vec3 E = wCenter * c.rgb;
    occlusion = wCenter * ao;
    for (int i = 0; i < 5; ++i) {
        float phi = TWO_PI * float(i) / 5.0;
        vec3 dir = normalize(cos60 * n + sin60 * (cos(phi) * t + sin(phi) * b));
        vec4 s = traceConeAO(origin, n, originHeight, dir, TAN_30, params, aoLambda, ao);
        E += wSide * s.rgb;
        occlusion += wSide * ao;
    }
    occlusion /= PI;
    return E;
}
