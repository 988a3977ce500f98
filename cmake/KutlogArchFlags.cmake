# The archs kutlog compiles its kernels for (see include/kutlog/dispatch.hpp), with the
# compiler flags of each. Also used by the benchmarks, which instantiate kernels per arch.
set(KUTLOG_ARCHS sse4_1 avx2 avx512)
set(KUTLOG_FLAGS_sse4_1 -msse4.1)
set(KUTLOG_FLAGS_avx2 -mavx2 -mfma)
# GCC 12 warns inside its own avx512fintrin.h, whose _mm512_undefined_ps initializes a vector
# with itself, at -O2 (maybe-uninitialized; uninitialized where a masked load feeds it); clang
# has no such warning (and warns about the unknown option).
set(KUTLOG_FLAGS_avx512 -mavx512f -mavx512cd -mavx512dq -mavx512bw -mavx512vl -mfma
    $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized -Wno-uninitialized>)
