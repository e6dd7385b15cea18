// Surface reflection: Lambert (baseColor / pi), plus a GGX lobe for glossy
// materials. A material with roughness 1 and metallic 0 is treated as purely
// Lambertian, which is the model of the path-traced references.
#include "lib/math.glsl"

bool isGlossy(float metallic, float roughness) {
    return metallic > 0.0 || roughness < 0.999;
}

// Returns BRDF * cos(theta_l) for unit N, L, V.
vec3 surfaceBrdfCos(vec3 base, float metallic, float roughness, vec3 N, vec3 L, vec3 V) {
    float NoL = max(dot(N, L), 0.0);
    if (!isGlossy(metallic, roughness)) return base / PI * NoL;
    vec3 H = normalize(L + V);
    float NoV = max(dot(N, V), 1e-4), NoH = max(dot(N, H), 0.0), VoH = max(dot(V, H), 0.0);
    float a = max(roughness * roughness, 1e-3), a2 = a * a;
    float d = NoH * NoH * (a2 - 1.0) + 1.0;
    float D = a2 / (PI * d * d);
    // Height-correlated Smith visibility.
    float gv = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    float gl = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    float Vis = 0.5 / max(gv + gl, 1e-6);
    vec3 F0 = mix(vec3(0.04), base, metallic);
    vec3 F = F0 + (1.0 - F0) * pow(1.0 - VoH, 5.0);
    vec3 diffuse = (1.0 - metallic) * (1.0 - F) * base / PI;
    return (diffuse + D * Vis * F) * NoL;
}
