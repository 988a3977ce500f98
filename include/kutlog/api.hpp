// kutlog/api.hpp: what the library exports. Every public header of include/kutlog wraps its
// declarations in KUTLOG_API_BEGIN / KUTLOG_API_END, which give them default visibility; the
// shared library (CMake's BUILD_SHARED_LIBS) is compiled with -fvisibility=hidden, so that
// nothing else it contains (the setup's internals, the per-arch kernels) is exported or can
// clash with a symbol of the program that loads it. Also declares detail::Inspector, the one
// friend of the public classes.
#pragma once

// Below C++20, this one #error and nothing else: every other header of kutlog is empty there
// (#if KUTLOG_HAS_CXX20), so that the compiler prints no cascade of errors after it.
#if __cplusplus < 202002L
#error "kutlog's headers need C++20 (-std=c++20 or later)"
#define KUTLOG_HAS_CXX20 0
#else
#define KUTLOG_HAS_CXX20 1

#if defined(__GNUC__) || defined(__clang__)
#define KUTLOG_API_BEGIN _Pragma("GCC visibility push(default)")
#define KUTLOG_API_END _Pragma("GCC visibility pop")
#else
#define KUTLOG_API_BEGIN
#define KUTLOG_API_END
#endif

namespace kutlog::detail {
// Reads the fitted kernels of the classes of kutlog/lobe.hpp and kutlog/sampling.hpp, for
// kutlog/inspect.hpp and the library's own dispatch; a friend of each.
struct Inspector;
}  // namespace kutlog::detail

#endif  // KUTLOG_HAS_CXX20
