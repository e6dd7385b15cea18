// Light evaluation in this project's units (docs/UNITS.md). Shared by the
// per-pixel lighting and the per-voxel light injection.

// Irradiance on a surface facing the light, arriving at P, and the unit vector
// from P toward the light. dist is the distance to the light (1e30 for a sun).
vec3 lightIrradiance(GpuLight light, vec3 P, out vec3 L, out float dist) {
    uint type = uint(light.position.w);
    if (type == LIGHT_DIRECTIONAL) {
        L = -light.direction.xyz;
        dist = 1e30;
        return light.radiant.rgb;  // E in W/m^2
    }
    vec3 toLight = light.position.xyz - P;
    float d2 = max(dot(toLight, toLight), 1e-12);
    dist = sqrt(d2);
    L = toLight / dist;
    if (type == LIGHT_AREA) {
        // Lambertian patch: I = L A cos(theta_e), and a disk of the patch's
        // area in the near field (exact on a disk's axis: pi L r^2 / (d^2 + r^2)).
        float c = dot(light.direction.xyz, -L);
        c = light.direction.w > 0.5 ? abs(c) : max(c, 0.0);
        return light.radiant.rgb * (c / (d2 + light.radiant.w));
    }
    vec3 E = light.radiant.rgb / d2;  // I / d^2
    if (type == LIGHT_SPOT) {
        // KHR_lights_punctual reference falloff, squared as CONVENTIONS.md states.
        float cosTheta = dot(-L, light.direction.xyz);
        float cosOuter = light.direction.w, cosInner = light.radiant.w;
        float t = clamp((cosTheta - cosOuter) / max(1e-3, cosInner - cosOuter), 0.0, 1.0);
        E *= t * t;
    }
    return E;
}
