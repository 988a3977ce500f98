// kutlog/api.hpp: KUTLOG_API_BEGIN/END give the public headers' declarations default
// visibility; the shared library hides everything else (-fvisibility=hidden). Also declares
// detail::Inspector, the one friend of the public classes.
#pragma once

#if __cplusplus < 202002L
#error "kutlog's headers need C++20 (-std=c++20 or later)"
#endif

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
