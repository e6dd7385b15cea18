// Keyframe sampling with glTF 2.0 sampler semantics (spec section 3.11 and
// Appendix C): the animated property is written into the node's local TRS.
#include <algorithm>
#include <cmath>

#include "scene/scene.h"

namespace dvsgi::scene {

namespace {

glm::quat toQuat(const glm::vec4& xyzw) { return glm::quat(xyzw.w, xyzw.x, xyzw.y, xyzw.z); }

// Shortest-arc slerp: q and -q are the same rotation, and interpolating
// towards the far one would spin the node the long way round.
glm::quat slerpShortest(glm::quat a, glm::quat b, float s) {
    if (glm::dot(a, b) < 0.0f) b = -b;
    float d = std::clamp(glm::dot(a, b), -1.0f, 1.0f);
    if (d > 0.9995f) return glm::normalize(a + s * (b - a));  // sin(theta) ~ 0
    float theta = std::acos(d);
    float sinTheta = std::sin(theta);
    float wa = std::sin((1.0f - s) * theta) / sinTheta;
    float wb = std::sin(s * theta) / sinTheta;
    return glm::normalize(a * wa + b * wb);
}

// Returns the sampled value as xyz or quaternion xyzw; false when the channel
// has too few values to be sampled at all.
bool sampleChannel(const AnimationChannel& ch, float t, glm::vec4& out) {
    const size_t keys = ch.times.size();
    const bool cubic = ch.interpolation == Interpolation::CubicSpline;
    const size_t stride = cubic ? 3 : 1;
    if (keys == 0 || ch.values.size() < keys * stride) return false;
    auto value = [&](size_t k) { return ch.values[k * stride + (cubic ? 1 : 0)]; };

    if (keys == 1 || t <= ch.times.front()) {
        out = value(0);
        return true;
    }
    if (t >= ch.times.back()) {
        out = value(keys - 1);
        return true;
    }
    // First key strictly after t; the segment is [k, k+1].
    size_t k1 = static_cast<size_t>(std::upper_bound(ch.times.begin(), ch.times.end(), t) - ch.times.begin());
    size_t k = k1 - 1;
    float t0 = ch.times[k], t1 = ch.times[k1];
    float dt = t1 - t0;
    float s = dt > 0.0f ? (t - t0) / dt : 0.0f;
    const bool rotation = ch.path == AnimPath::Rotation;

    switch (ch.interpolation) {
    case Interpolation::Step:
        out = value(k);
        return true;
    case Interpolation::Linear:
        if (rotation) {
            glm::quat q = slerpShortest(toQuat(value(k)), toQuat(value(k1)), s);
            out = glm::vec4(q.x, q.y, q.z, q.w);
        } else {
            out = glm::mix(value(k), value(k1), s);
        }
        return true;
    case Interpolation::CubicSpline: {
        // Hermite basis with tangents scaled by the key spacing, as glTF defines.
        glm::vec4 p0 = value(k), p1 = value(k1);
        glm::vec4 m0 = dt * ch.values[k * 3 + 2];    // out-tangent of key k
        glm::vec4 m1 = dt * ch.values[k1 * 3 + 0];   // in-tangent of key k+1
        float s2 = s * s, s3 = s2 * s;
        out = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
        if (rotation) {
            float len = glm::length(out);
            out = len > 0.0f ? out / len : glm::vec4(0, 0, 0, 1);
        }
        return true;
    }
    }
    return false;
}

}  // namespace

void applyAnimations(Scene& scene, float t) {
    for (const Animation& anim : scene.animations) {
        for (const AnimationChannel& ch : anim.channels) {
            if (ch.node < 0 || ch.node >= static_cast<int>(scene.nodes.size())) continue;
            glm::vec4 v;
            if (!sampleChannel(ch, t, v)) continue;
            Node& n = scene.nodes[ch.node];
            switch (ch.path) {
            case AnimPath::Translation: n.translation = glm::vec3(v); break;
            case AnimPath::Scale: n.scale = glm::vec3(v); break;
            case AnimPath::Rotation: n.rotation = glm::normalize(toQuat(v)); break;
            }
        }
    }
}

}  // namespace dvsgi::scene
