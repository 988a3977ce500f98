// xsimd first, then kutlog/simd/: kutlog's fix of xsimd must not depend on the order.
#include <xsimd/xsimd.hpp>

#include <kutlog/simd/lobe.hpp>

#include "simd_instances.hpp"
