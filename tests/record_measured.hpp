// The largest error a test measured, as a property of the test (gtest's XML output, which
// GTEST_OUTPUT=xml:<dir>/ writes): how the measured columns of kutlog/accuracy.hpp are read off
// the sweeps that assert them (scripts/measured-bounds.py).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>

namespace kutlog {

// Records `value` as the property `name` unless this process recorded a larger one.
inline void record_max(const std::string& name, double value) {
  static std::map<std::string, double> maxima;
  double& max = maxima.try_emplace(name, value).first->second;
  max = std::max(max, value);
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", max);
  testing::Test::RecordProperty(name, text);
}

}  // namespace kutlog
