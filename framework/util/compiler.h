// Attributes only some compilers know, each behind a check, so that GCC,
// Clang and MSVC all build the framework without a warning. They change
// speed, never results.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define PATHLAB_NOINLINE [[gnu::noinline]]
#define PATHLAB_ALWAYS_INLINE [[gnu::always_inline]]
#define PATHLAB_FLATTEN [[gnu::flatten]]  // inline every call in the function's body
#elif defined(_MSC_VER)
#define PATHLAB_NOINLINE __declspec(noinline)
#define PATHLAB_ALWAYS_INLINE
#define PATHLAB_FLATTEN
#else
#define PATHLAB_NOINLINE
#define PATHLAB_ALWAYS_INLINE
#define PATHLAB_FLATTEN
#endif
