// kutlog/api.hpp: what the library exports.
//
// Everything a public header of include/kutlog declares is kutlog's API. Each wraps its
// declarations in KUTLOG_API_BEGIN / KUTLOG_API_END, which give them default visibility; the
// shared library is compiled with -fvisibility=hidden (CMake's BUILD_SHARED_LIBS), so that
// nothing else it contains (the setup's internals, the per-arch kernels) is exported or can
// clash with a symbol of the program that loads it.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define KUTLOG_API_BEGIN _Pragma("GCC visibility push(default)")
#define KUTLOG_API_END _Pragma("GCC visibility pop")
#else
#define KUTLOG_API_BEGIN
#define KUTLOG_API_END
#endif
