// Four floats processed together: SSE2 where the compiler has it (every
// x86-64), plain arrays elsewhere, with the same results bit for bit. Only
// what the wide BVH needs. Comparisons return a 4-bit mask, bit l for lane l.
// min/max follow SSE: when either operand is NaN they return the second, so
// max(NaN-prone value, running limit) keeps the limit.
#pragma once

#include <cmath>

#if defined(__SSE2__) || defined(_M_X64)  // every x86-64 compiler: GCC, Clang, MSVC
#include <emmintrin.h>
#endif

namespace pathlab::lanes {

#if defined(__SSE2__) || defined(_M_X64)  // every x86-64 compiler: GCC, Clang, MSVC

struct F4 {
  __m128 v;
};
inline F4 load(const float* p) { return {_mm_load_ps(p)}; }  // p 16-byte aligned
inline F4 splat(float x) { return {_mm_set1_ps(x)}; }
inline void store(float* p, F4 a) { _mm_store_ps(p, a.v); }
inline F4 operator+(F4 a, F4 b) { return {_mm_add_ps(a.v, b.v)}; }
inline F4 operator-(F4 a, F4 b) { return {_mm_sub_ps(a.v, b.v)}; }
inline F4 operator*(F4 a, F4 b) { return {_mm_mul_ps(a.v, b.v)}; }
inline F4 operator/(F4 a, F4 b) { return {_mm_div_ps(a.v, b.v)}; }
inline F4 min(F4 a, F4 b) { return {_mm_min_ps(a.v, b.v)}; }
inline F4 max(F4 a, F4 b) { return {_mm_max_ps(a.v, b.v)}; }
inline int operator<(F4 a, F4 b) { return _mm_movemask_ps(_mm_cmplt_ps(a.v, b.v)); }
inline int operator<=(F4 a, F4 b) { return _mm_movemask_ps(_mm_cmple_ps(a.v, b.v)); }
inline int operator>(F4 a, F4 b) { return _mm_movemask_ps(_mm_cmpgt_ps(a.v, b.v)); }
inline int operator>=(F4 a, F4 b) { return _mm_movemask_ps(_mm_cmpge_ps(a.v, b.v)); }
inline int operator==(F4 a, F4 b) { return _mm_movemask_ps(_mm_cmpeq_ps(a.v, b.v)); }
inline F4 operator-(F4 a) { return {_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))}; }  // the sign flipped, as unary minus
inline F4 sqrt(F4 a) { return {_mm_sqrt_ps(a.v)}; }
// a's magnitude with b's sign bit, as std::copysign.
inline F4 copysign(F4 a, F4 b) {
  const __m128 sign = _mm_set1_ps(-0.0f);
  return {_mm_or_ps(_mm_andnot_ps(sign, a.v), _mm_and_ps(sign, b.v))};
}

#else

struct F4 {
  float v[4];
};
template <class Op>
inline F4 each(F4 a, F4 b, Op op) {
  return {{op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])}};
}
template <class Op>
inline int maskOf(F4 a, F4 b, Op op) {
  return int(op(a.v[0], b.v[0])) | int(op(a.v[1], b.v[1])) << 1 | int(op(a.v[2], b.v[2])) << 2 |
         int(op(a.v[3], b.v[3])) << 3;
}
inline F4 load(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
inline F4 splat(float x) { return {{x, x, x, x}}; }
inline void store(float* p, F4 a) {
  for (int l = 0; l < 4; ++l) p[l] = a.v[l];
}
inline F4 operator+(F4 a, F4 b) { return each(a, b, [](float x, float y) { return x + y; }); }
inline F4 operator-(F4 a, F4 b) { return each(a, b, [](float x, float y) { return x - y; }); }
inline F4 operator*(F4 a, F4 b) { return each(a, b, [](float x, float y) { return x * y; }); }
inline F4 operator/(F4 a, F4 b) { return each(a, b, [](float x, float y) { return x / y; }); }
inline F4 min(F4 a, F4 b) { return each(a, b, [](float x, float y) { return x < y ? x : y; }); }
inline F4 max(F4 a, F4 b) { return each(a, b, [](float x, float y) { return x > y ? x : y; }); }
inline int operator<(F4 a, F4 b) { return maskOf(a, b, [](float x, float y) { return x < y; }); }
inline int operator<=(F4 a, F4 b) { return maskOf(a, b, [](float x, float y) { return x <= y; }); }
inline int operator>(F4 a, F4 b) { return maskOf(a, b, [](float x, float y) { return x > y; }); }
inline int operator>=(F4 a, F4 b) { return maskOf(a, b, [](float x, float y) { return x >= y; }); }
inline int operator==(F4 a, F4 b) { return maskOf(a, b, [](float x, float y) { return x == y; }); }
inline F4 operator-(F4 a) { return {{-a.v[0], -a.v[1], -a.v[2], -a.v[3]}}; }
inline F4 sqrt(F4 a) { return {{std::sqrt(a.v[0]), std::sqrt(a.v[1]), std::sqrt(a.v[2]), std::sqrt(a.v[3])}}; }
inline F4 copysign(F4 a, F4 b) { return each(a, b, [](float x, float y) { return std::copysign(x, y); }); }

#endif

}  // namespace pathlab::lanes
