// The guard zones of the array contract's tests (tests/, tests/fuzz/): nothing outside
// [0, count) of an output may be written, whatever the count and the alignment.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace kutlog::tools {

// `count` floats at a misalignment of `offset` floats between guard zones wider than a batch
// of any arch. The zones hold a byte pattern and ASan poisons them: any access outside
// [0, count) is reported by ASan at once and, without ASan, a write by changed_guard_byte().
class GuardedOutput {
 public:
  GuardedOutput(std::size_t count, std::size_t offset);
  ~GuardedOutput();
  GuardedOutput(const GuardedOutput&) = delete;
  GuardedOutput& operator=(const GuardedOutput&) = delete;

  float* data() { return buffer_.data() + kGuard + offset_; }
  const float* data() const { return buffer_.data() + kGuard + offset_; }
  std::span<float> values() { return {data(), count_}; }
  // The index (relative to data(), so negative before it) of the first guard byte that
  // differs from the pattern; false if none does.
  bool changed_guard_byte(std::ptrdiff_t& index) const;

 private:
  static constexpr std::size_t kGuard = 32;
  std::size_t count_, offset_;
  std::vector<float> buffer_;
};

}  // namespace kutlog::tools
