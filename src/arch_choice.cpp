// Run-time choice of the arch: the registry's names, the CPU's support, KUTLOG_ARCH,
// KUTLOG_CPU_HIDE and the forced arch. It references no kernel table (src/dispatch.cpp holds
// them), so that a program whose only kutlog calls are scalar links none. Compiled with the
// baseline flags only: nothing here may execute an instruction the CPU might lack.
#include "arch_choice.hpp"

#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>

#include "cpu_features.hpp"
#include "kutlog/dispatch.hpp"

namespace kutlog {
namespace {

// The registry (cmake/KutlogArchs.cmake) as a table, indexed by Arch.
struct ArchEntry {
  std::string_view name;
  std::string_view cpu_features;
};
constexpr ArchEntry kArchEntries[] = {
#define KUTLOG_ARCH_ENTRY(id, name, xsimd_arch, cpu_features, ...) {name, cpu_features},
    KUTLOG_ARCHS(KUTLOG_ARCH_ENTRY)
#undef KUTLOG_ARCH_ENTRY
};
static_assert(std::size(kArchEntries) == kCompiledArchs.size());

const ArchEntry& entry(Arch arch) { return kArchEntries[static_cast<std::size_t>(arch)]; }

constexpr Arch kBaselineArch = kCompiledArchs.back();

using ArchSupport = std::array<bool, kCompiledArchs.size()>;

std::string name_list(const auto& archs) {
  std::string names;
  for (Arch arch : archs) names += (names.empty() ? "" : ", ") + std::string(arch_name(arch));
  return names.empty() ? "none" : names;
}

std::optional<Arch> find_arch(std::string_view name) {
  for (Arch arch : kCompiledArchs)
    if (name == arch_name(arch)) return arch;
  return std::nullopt;
}

// source: "" for parse_arch, or the environment variable that gave the name.
std::string unknown_arch_message(std::string_view name, std::string_view source = "") {
  return "kutlog: " + std::string(source) + "unknown arch '" + std::string(name) +
         "'; valid: " + name_list(kCompiledArchs);
}

// What this CPU runs, and what was wrong with the environment variables that steer the choice:
// a bad name is ignored, reported by arch_environment_error() and once on stderr.
struct CpuView {
  ArchSupport support{};
  std::string environment_error;
};

// KUTLOG_CPU_HIDE=avx512[,avx2...] makes kutlog treat this CPU as lacking those archs and
// every arch ranked above them (for avx2, avx512 too), so that the fallbacks and the
// unsupported-arch errors can be tested on a machine that has everything (glibc's hwcaps
// tunables do the same for glibc).
void hide_archs_named_in_environment(CpuView& view) {
  const char* hidden = std::getenv("KUTLOG_CPU_HIDE");
  if (!hidden) return;
  std::string_view names = hidden;
  while (!names.empty()) {
    const std::size_t comma = names.find(',');
    const std::string_view name = names.substr(0, comma);
    if (const std::optional<Arch> arch = find_arch(name)) {
      for (std::size_t above = 0; above <= static_cast<std::size_t>(*arch); ++above)
        view.support[above] = false;
    } else {
      view.environment_error = unknown_arch_message(name, "KUTLOG_CPU_HIDE: ");
    }
    names = comma == std::string_view::npos ? std::string_view() : names.substr(comma + 1);
  }
}

void report_environment_error(const std::string& error) {
  if (!error.empty()) std::fprintf(stderr, "%s (ignored)\n", error.c_str());
}

const CpuView& cpu_view() {
  static const CpuView view = [] {
    CpuView detected;
    for (Arch arch : kCompiledArchs)
      detected.support[static_cast<std::size_t>(arch)] =
          detail::cpu_has_features(entry(arch).cpu_features);
    hide_archs_named_in_environment(detected);
    report_environment_error(detected.environment_error);
    return detected;
  }();
  return view;
}

void require_supported(Arch arch, const char* who) {
  if (!arch_supported(arch))
    throw std::runtime_error(std::string("kutlog: ") + who + " arch " +
                             std::string(arch_name(arch)) +
                             " is not supported by this machine (supported: " +
                             name_list(supported_archs()) + ")");
}

// The automatic choice: KUTLOG_ARCH if it names a supported arch, else the best supported
// arch (none when the CPU lacks the baseline). Computed once, thread-safely.
struct AutomaticChoice {
  std::optional<Arch> arch;
  std::string environment_error;
};
const AutomaticChoice& automatic_choice() {
  static const AutomaticChoice choice = [] {
    AutomaticChoice chosen;
    const std::vector<Arch> archs = supported_archs();
    if (!archs.empty()) chosen.arch = archs.front();
    const char* forced = std::getenv("KUTLOG_ARCH");
    if (!forced || !*forced) return chosen;
    const std::optional<Arch> named = find_arch(forced);
    if (!named)
      chosen.environment_error = unknown_arch_message(forced, "KUTLOG_ARCH: ");
    else if (!arch_supported(*named))
      chosen.environment_error = "kutlog: KUTLOG_ARCH names arch " + std::string(forced) +
                                 ", not supported by this machine (supported: " +
                                 name_list(archs) + ")";
    else
      chosen.arch = named;
    report_environment_error(chosen.environment_error);
    return chosen;
  }();
  return choice;
}

constexpr int kNotForced = -1;
std::atomic<int> forced_arch{kNotForced};

}  // namespace

std::string_view arch_name(Arch arch) { return entry(arch).name; }

Arch parse_arch(std::string_view name) {
  if (const std::optional<Arch> arch = find_arch(name)) return *arch;
  throw std::invalid_argument(unknown_arch_message(name));
}

bool arch_supported(Arch arch) { return cpu_view().support[static_cast<std::size_t>(arch)]; }

std::vector<Arch> supported_archs() {
  std::vector<Arch> archs;
  for (Arch arch : kCompiledArchs)
    if (arch_supported(arch)) archs.push_back(arch);
  return archs;
}

Arch active_arch() {
  const int forced = forced_arch.load(std::memory_order_relaxed);
  if (forced != kNotForced) return static_cast<Arch>(forced);
  const std::optional<Arch> automatic = automatic_choice().arch;
  if (!automatic)
    throw std::runtime_error("kutlog: this CPU lacks " + std::string(arch_name(kBaselineArch)) +
                             ", kutlog's baseline arch (compiled: " + name_list(kCompiledArchs) +
                             ")");
  return *automatic;
}

void detail::require_runnable_arch() { (void)active_arch(); }

std::string arch_environment_error() {
  const std::string& hide_error = cpu_view().environment_error;
  const std::string& arch_error = automatic_choice().environment_error;
  return hide_error.empty() || arch_error.empty() ? hide_error + arch_error
                                                  : hide_error + "; " + arch_error;
}

void detail::choose_forced_arch(Arch arch) {
  require_supported(arch, "forced");
  forced_arch.store(static_cast<int>(arch), std::memory_order_relaxed);
}

void detail::clear_forced_arch() { forced_arch.store(kNotForced, std::memory_order_relaxed); }

}  // namespace kutlog
