// Where the lobe kernels cut to 0, for the setups of src/lobe.cpp and src/per_lane_lobe.cpp.
#pragma once

#include <algorithm>
#include <cmath>

namespace kutlog::detail {

// The largest float at or below a lobe's cut t = cos(gran), and below 1: cos(gran) < 1 for
// every lobe, also where it rounds to 1 in float (n from about 1e7) or in double (1e16).
// A cut rounded up instead would zero t = 1, the peak.
inline float float_at_or_below_cut(double cut) {
  float t = float(cut);
  if (double(t) > cut) t = std::nextafter(t, -1.0f);
  return std::min(t, std::nextafter(1.0f, 0.0f));
}

}  // namespace kutlog::detail
