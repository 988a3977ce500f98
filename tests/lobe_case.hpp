// A lobe's parameters, for parameterized tests.
#pragma once

namespace kutlog {

struct LobeCase {
  double n;
  int k;
  double Q;
};

}  // namespace kutlog
