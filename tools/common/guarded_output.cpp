#include "common/guarded_output.hpp"

#include <sanitizer/asan_interface.h>

#include <cstdint>

namespace kutlog::tools {
namespace {
std::uint8_t guard_pattern(std::size_t byte) { return std::uint8_t(0xa5 ^ (byte * 7)); }
}  // namespace

GuardedOutput::GuardedOutput(std::size_t count, std::size_t offset)
    : count_(count), offset_(offset), buffer_(kGuard + offset + count + kGuard) {
  auto* bytes = reinterpret_cast<std::uint8_t*>(buffer_.data());
  for (std::size_t i = 0; i < buffer_.size() * sizeof(float); ++i) bytes[i] = guard_pattern(i);
  ASAN_POISON_MEMORY_REGION(buffer_.data(), (kGuard + offset) * sizeof(float));
  ASAN_POISON_MEMORY_REGION(data() + count, kGuard * sizeof(float));
}

GuardedOutput::~GuardedOutput() {
  ASAN_UNPOISON_MEMORY_REGION(buffer_.data(), buffer_.size() * sizeof(float));
}

bool GuardedOutput::changed_guard_byte(std::ptrdiff_t& index) const {
  ASAN_UNPOISON_MEMORY_REGION(buffer_.data(), buffer_.size() * sizeof(float));
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(buffer_.data());
  const std::size_t first = (kGuard + offset_) * sizeof(float);
  const std::size_t end = first + count_ * sizeof(float);
  bool changed = false;
  for (std::size_t i = 0; i < buffer_.size() * sizeof(float) && !changed; ++i)
    if ((i < first || i >= end) && bytes[i] != guard_pattern(i))
      changed = true, index = std::ptrdiff_t(i) - std::ptrdiff_t(first);
  ASAN_POISON_MEMORY_REGION(buffer_.data(), first);
  ASAN_POISON_MEMORY_REGION(bytes + end, buffer_.size() * sizeof(float) - end);
  return changed;
}

}  // namespace kutlog::tools
