// Constants every shader shares, defined once.
#ifndef DVSGI_LIB_MATH_GLSL
#define DVSGI_LIB_MATH_GLSL

const float PI = 3.14159265358979;
const float TWO_PI = 6.28318530717959;

// Rec. 709 / sRGB primaries, linear radiance.
float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

#endif
