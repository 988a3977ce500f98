// A lobe's parameters, for parameterized tests, and the test names they give.
#pragma once

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace kutlog {

struct LobeCase {
  double n;
  int k;
  double Q;
};

// gtest prints a case as "n=100 k=3 Q=0.5" (not its bytes) in failures and in ctest's names.
inline void PrintTo(const LobeCase& lobe, std::ostream* os) {
  *os << "n=" << lobe.n << " k=" << lobe.k << " Q=" << lobe.Q;
}

// "n100_k3_Q0_5", "n1e_300_k1_Q0_5": gtest allows only letters, digits and '_' in names.
inline std::string lobe_case_name(const testing::TestParamInfo<LobeCase>& info) {
  char name[64];
  std::snprintf(name, sizeof name, "n%g_k%d_Q%g", info.param.n, info.param.k, info.param.Q);
  std::string result = name;
  for (char& c : result)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return result;
}

// The sampling tests' grid (issue 14): n in {k+1, 10, 100, 1000, 10^4}, k in {1, 3, 5},
// Q in {0.1, 0.5, 0.9}.
inline std::vector<LobeCase> sampling_grid() {
  std::vector<LobeCase> grid;
  for (int k : {1, 3, 5})
    for (double Q : {0.1, 0.5, 0.9})
      for (double n : {k + 1.0, 10.0, 100.0, 1000.0, 10000.0}) grid.push_back({n, k, Q});
  return grid;
}

}  // namespace kutlog
