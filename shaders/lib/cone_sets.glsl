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
        float w = PI * z / sumCos;
        float ao;
        vec4 c = traceConeAO(origin, n, originHeight, dir, TAN_CONE16, params, aoLambda, false, ao);
        E += w * c.rgb;
        occlusion += w * ao;
    }
    occlusion /= PI;
    return E;
}
