// Names of per-arch test instances: the arch's name, as gtest allows ("sse4.1" -> "sse4_1").
#pragma once

#include <string>

#include "kutlog/dispatch.hpp"

namespace kutlog {

inline std::string arch_test_name(const testing::TestParamInfo<Arch>& info) {
  std::string name(arch_name(info.param));
  for (char& c : name)
    if (c == '.') c = '_';
  return name;
}

}  // namespace kutlog
