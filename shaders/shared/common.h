// Lets one header declare data for both C++ and GLSL. In C++ the GLSL vector
// types map to glm and constants become constexpr; std430/std140 layouts are
// kept by using only 16-byte members (vec4, ivec4, uvec4, mat4) in structs, and
// every struct's size is checked with static_assert next to its definition.
#ifndef DVSGI_SHARED_COMMON_H
#define DVSGI_SHARED_COMMON_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace dvsgi::shader {
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using ivec3 = glm::ivec3;
using ivec4 = glm::ivec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = uint32_t;
}  // namespace dvsgi::shader
#define DVSGI_BEGIN namespace dvsgi::shader {
#define DVSGI_END }
#define DVSGI_CONST(type, name, value) inline constexpr type name = value
#define DVSGI_CHECK_SIZE(type, bytes) static_assert(sizeof(type) == (bytes), #type " layout changed")
// A function written once in the subset of C++ and GLSL both accept.
#define DVSGI_FUNCTION inline
#else
#define DVSGI_BEGIN
#define DVSGI_END
#define DVSGI_CONST(type, name, value) const type name = value
#define DVSGI_CHECK_SIZE(type, bytes)
#define DVSGI_FUNCTION
#endif

#endif
