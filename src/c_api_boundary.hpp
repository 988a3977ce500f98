// The C API's boundary (kutlog/kutlog.h): its handles, and how every call checks its inputs and
// turns the C++ exceptions into a status and a message. Shared by src/c_api_lobe.cpp (a lobe's
// scalar calls, which link no kernel table) and src/c_api.cpp (the rest).
#pragma once

#include <cstddef>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>

#include "kutlog/kutlog.h"
#include "kutlog/lobe.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"

struct kutlog_lobe {
  kutlog::Lobe lobe;
};
struct kutlog_per_lane_lobe {
  kutlog::PerLaneLobe lobe;
};
struct kutlog_sampler {
  kutlog::LobeSampler sampler;
};

namespace kutlog::c_api {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

inline kutlog_status report(kutlog_error* error, kutlog_status code, const char* message) {
  if (error) {
    error->code = code;
    std::snprintf(error->message, sizeof error->message, "%s", message);
  }
  return code;
}

// body() under the boundary's rule: its status, or the exception's.
template <class Body>
kutlog_status guarded(kutlog_error* error, Body body) noexcept {
  try {
    const kutlog_status status = body();
    if (status == KUTLOG_OK) report(error, KUTLOG_OK, "");
    return status;
  } catch (const std::invalid_argument& exception) {
    return report(error, KUTLOG_INVALID_ARGUMENT, exception.what());
  } catch (const std::bad_alloc&) {
    return report(error, KUTLOG_OUT_OF_MEMORY, "kutlog: out of memory");
  } catch (const std::runtime_error& exception) {
    // A CPU without the baseline arch, or a forced arch it lacks; else a setup that met no bound.
    const bool unsupported = std::string(exception.what()).find("no kernel") == std::string::npos;
    return report(error, unsupported ? KUTLOG_UNSUPPORTED : KUTLOG_INTERNAL_ERROR,
                  exception.what());
  } catch (const std::exception& exception) {
    return report(error, KUTLOG_INTERNAL_ERROR, exception.what());
  } catch (...) {
    return report(error, KUTLOG_INTERNAL_ERROR, "kutlog: unknown exception");
  }
}

// The C enums' counts of constants (kutlog/kutlog.h), and their checks.
constexpr int kVariants = 3, kNormalizations = 2;
inline bool valid_variant(kutlog_variant variant) { return variant >= 0 && variant < kVariants; }
inline bool valid_normalization(kutlog_normalization normalization) {
  return normalization >= 0 && normalization < kNormalizations;
}

// The checks of one call, in order, the first failure reported: Check(error).handle(...)...
class Check {
 public:
  explicit Check(kutlog_error* error) : error_(error) {}
  operator kutlog_status() const { return status_; }

  Check& pointer(const void* pointer, const char* name, const char* valid) {
    if (!pointer) fail(std::string(name) + " is NULL; valid: " + valid);
    return *this;
  }
  Check& handle(const void* handle, const char* name) {
    return pointer(handle, name, "a handle from its create call");
  }
  Check& in_range(int value, int count, const char* name, const char* valid) {
    if (value < 0 || value >= count)
      fail(std::string(name) + " = " + std::to_string(value) + " is out of range; valid: " + valid);
    return *this;
  }
  Check& variant(kutlog_variant variant, const char* name = "variant") {
    return in_range(variant, kVariants, name,
                    "KUTLOG_PRECISE, KUTLOG_FAST or KUTLOG_DETERMINISTIC");
  }
  Check& normalization(kutlog_normalization normalization,
                       const char* name = "normalization") {
    return in_range(normalization, kNormalizations, name,
                    "KUTLOG_UNNORMALIZED or KUTLOG_EXACT_COEF");
  }
  Check& options(const kutlog_shade_options& options) {
    return variant(options.variant, "options->variant")
        .normalization(options.normalization, "options->normalization")
        .in_range(options.reflection, 2, "options->reflection",
                  "KUTLOG_REFLECT_BLINN or KUTLOG_REFLECT_PHONG");
  }
  // The rule of every array: count 0 takes NULL; else each array non-NULL, and count at most
  // KUTLOG_MAX_COUNT.
  struct Array {
    const char* name;
    const void* pointer;
  };
  Check& arrays(std::size_t count, std::initializer_list<Array> arrays) {
    if (count == 0) return *this;
    if (count > std::size_t(KUTLOG_MAX_COUNT))
      fail("count = " + std::to_string(count) + " is out of range; valid: [0, " +
           std::to_string(KUTLOG_MAX_COUNT) + "] (KUTLOG_MAX_COUNT)");
    for (const Array& array : arrays)
      if (!array.pointer)
        fail(std::string(array.name) + " is NULL with count = " + std::to_string(count) +
             "; valid: NULL only with count 0");
    return *this;
  }

 private:
  void fail(const std::string& message) {
    if (status_ == KUTLOG_OK) status_ = report(error_, KUTLOG_INVALID_ARGUMENT, ("kutlog: " + message).c_str());
  }
  kutlog_error* error_;
  kutlog_status status_ = KUTLOG_OK;
};

inline kutlog::ShadeOptions options_of(const kutlog_shade_options& options) {
  return {kutlog::Variant(options.variant), kutlog::Normalization(options.normalization),
          kutlog::Reflection(options.reflection), options.times_n_dot_l != 0};
}
// Creates a handle around a new C++ object, or reports why not; *handle is NULL then.
template <class Handle, class... Arguments>
kutlog_status create(Handle** handle, kutlog_error* error, Arguments... arguments) {
  if (handle) *handle = nullptr;
  return guarded(error, [&] {
    if (const kutlog_status status = Check(error).pointer(handle, "the handle's address", "where to write the new handle"))
      return status;
    *handle = new Handle{{arguments...}};
    return KUTLOG_OK;
  });
}

}  // namespace kutlog::c_api
