// kutlog/simd/ first, then xsimd.
#include <kutlog/simd/lobe.hpp>

#include <xsimd/xsimd.hpp>

#include "simd_instances.hpp"
