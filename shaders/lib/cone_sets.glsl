// Sixteen cones over the hemisphere around n, for the per-pixel diffuse gather:
// equal solid angle each (2 pi / 16 sr, half-angle 20.4 degrees), directions on
// a spiral that is uniform in cos(theta), weights pi * cos(theta_i) / sum cos
// so a uniform environment of radiance L gives irradiance pi * L.
// Needs lib/cone_trace.glsl. Returns the irradiance; `occlusion` gets the
// weighted mean opacity of the cones (weights / pi).
const float TAN_CONE16 = 0.3718;  // tan(20.4 degrees)

vec3 gatherIrradiance16(vec3 origin, vec3 n, float originHeight, ConeParams params, float aoLambda, out float occlusion) {
    vec3 t, b;
    coneBasis(n, t, b);
    float sumCos = 0.0;
    for (int i = 0; i < 16; ++i) sumCos += 1.0 - (float(i) + 0.5) / 16.0;
    vec3 E = vec3(0.0);
    occlusion = 0.0;
    for (int i = 0; i < 16; ++i) {
        float z = 1.0 - (float(i) + 0.5) / 16.0;
        float r = sqrt(max(1.0 - z * z, 0.0));
        float phi = 2.39996323 * float(i);  // golden angle
        vec3 dir = normalize(z * n + r * (cos(phi) * t + sin(phi) * b));
        float w = 3.14159265 * z / sumCos;
        float ao;
        vec4 c = traceConeAO(origin, n, originHeight, dir, TAN_CONE16, params, aoLambda, ao);
        E += w * c.rgb;
        occlusion += w * ao;
    }
    occlusion /= 3.14159265;
    return E;
}

// The paper's six 60-degree cones (one along n, five at 60 degrees around it),
// cosine-normalized as above, with distance-weighted occlusion for AO.
vec3 gatherIrradiance6AO(vec3 origin, vec3 n, float originHeight, ConeParams params, float aoLambda, out float occlusion) {
    vec3 t, b;
    coneBasis(n, t, b);
    const float sin60 = 0.8660254, cos60 = 0.5;
    const float wCenter = 3.14159265 / 3.5, wSide = 3.14159265 * 0.5 / 3.5;
    float ao;
    vec4 c = traceConeAO(origin, n, originHeight, n, TAN_30, params, aoLambda, ao);
    vec3 E = wCenter * c.rgb;
    occlusion = wCenter * ao;
    for (int i = 0; i < 5; ++i) {
        float phi = 6.28318531 * float(i) / 5.0;
        vec3 dir = normalize(cos60 * n + sin60 * (cos(phi) * t + sin(phi) * b));
        vec4 s = traceConeAO(origin, n, originHeight, dir, TAN_30, params, aoLambda, ao);
        E += wSide * s.rgb;
        occlusion += wSide * ao;
    }
    occlusion /= 3.14159265;
    return E;
}
