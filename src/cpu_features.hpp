// What this CPU can run: the features that the arch registry (cmake/KutlogArchs.cmake) names
// in each arch's CPU field. Compiled with the baseline flags only.
#pragma once

#include <string_view>

namespace kutlog::detail {

// True if the CPU has every feature of the space-separated list and the OS has enabled the
// registers they use. Detected once; false for a feature that is not known.
bool cpu_has_features(std::string_view features);

// Throws std::runtime_error if this CPU runs none of the compiled archs (src/dispatch.cpp). The
// constructors of Lobe, PerLaneLobe, PowerPoly and LobeSampler call it, so that their noexcept
// array calls always find an arch.
void require_runnable_arch();

}  // namespace kutlog::detail
