// kutlog/api.hpp: KUTLOG_API_BEGIN/END give the public headers' declarations default
// visibility; the shared library hides everything else (-fvisibility=hidden).
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define KUTLOG_API_BEGIN _Pragma("GCC visibility push(default)")
#define KUTLOG_API_END _Pragma("GCC visibility pop")
#else
#define KUTLOG_API_BEGIN
#define KUTLOG_API_END
#endif
