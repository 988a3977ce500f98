// The parameter contract: an invalid parameter throws std::invalid_argument whose message
// names the parameter ("n = ...") and its valid range.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace kutlog {

inline void expect_invalid(const std::function<void()>& call, const std::string& name,
                           const std::string& range) {
  try {
    call();
    ADD_FAILURE() << "no exception for " << name;
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(name + " = "), std::string::npos) << message;
    EXPECT_NE(message.find(range), std::string::npos) << message;
  }
}

}  // namespace kutlog
