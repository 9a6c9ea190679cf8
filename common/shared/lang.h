// Language bridge: the shared headers are written in the intersection of GLSL 4.60 and C++17.
// In C++ the GLSL vocabulary (vec3, uint, dot, mix, ...) is aliased to GLM inside namespace tp;
// in GLSL the C++-only words used by the headers are defined away.
//
// Rules for every file that includes this (docs/design.md, "The shared headers"):
// no templates, references, default arguments, enums, recursion or pointers; float literals
// carry `f`, unsigned ones `u`; out/inout parameters through OUT()/INOUT(); every function pure.
#ifndef TP_SHARED_LANG_H
#define TP_SHARED_LANG_H

#ifdef __cplusplus

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

namespace tp {
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using ivec2 = glm::ivec2;
using ivec3 = glm::ivec3;
using uvec2 = glm::uvec2;
using uvec3 = glm::uvec3;
using uvec4 = glm::uvec4;
using mat3 = glm::mat3;
using uint = std::uint32_t;

using glm::abs;
using glm::acos;
using glm::atan;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::dot;
using glm::exp;
using glm::exp2;
using glm::floatBitsToInt;
using glm::floatBitsToUint;
using glm::floor;
using glm::fract;
using glm::intBitsToFloat;
using glm::inversesqrt;
using glm::isinf;
using glm::isnan;
using glm::length;
using glm::log;
using glm::log2;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::pow;
using glm::reflect;
using glm::sign;
using glm::sin;
using glm::sqrt;
using glm::tan;
using glm::uintBitsToFloat;

// GLSL's bitfieldReverse of a 32-bit word (bit n moves to bit 31 - n): the bytes swapped, then
// the bits of each byte reversed in three mask-and-shift steps. GLM's version takes five such
// steps (16-, 8-, 4-, 2- and 1-bit blocks); the byte swap does the first two in one instruction.
inline uint bitfieldReverse(uint x) {
    x = __builtin_bswap32(x);
    x = ((x >> 4u) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4u);
    x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
    return ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
}

// The high 32 bits of the 64-bit product a * b: GLSL's umulExtended, here through uint64.
inline uint umul_hi(uint a, uint b) {
    return uint((uint64_t(a) * uint64_t(b)) >> 32u);
}
} // namespace tp

#define TP_NAMESPACE_BEGIN namespace tp {
#define TP_NAMESPACE_END }
#define OUT(T) T&
#define INOUT(T) T&

#else // GLSL

#define TP_NAMESPACE_BEGIN
#define TP_NAMESPACE_END
#define OUT(T) out T
#define INOUT(T) inout T
#define inline
#define static

// The high 32 bits of the 64-bit product a * b (the C++ side multiplies in uint64).
uint umul_hi(uint a, uint b) {
    uint hi;
    uint lo;
    umulExtended(a, b, hi, lo);
    return hi;
}

#endif

#endif // TP_SHARED_LANG_H
