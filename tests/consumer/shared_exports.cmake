# cmake -DLIBRARY=<libkutlog.so> -P shared_exports.cmake
# The shared library carries its SONAME and exports the API, not its internals.
execute_process(COMMAND objdump -p ${LIBRARY} OUTPUT_VARIABLE headers COMMAND_ERROR_IS_FATAL ANY)
if(NOT headers MATCHES "SONAME +libkutlog\\.so\\.[0-9]+")
  message(FATAL_ERROR "${LIBRARY} has no SONAME libkutlog.so.<major>")
endif()
execute_process(COMMAND nm -DC --defined-only ${LIBRARY} OUTPUT_VARIABLE symbols
                COMMAND_ERROR_IS_FATAL ANY)
# Lobe's array eval is inline up to the active arch's loop: its first call goes out of line.
foreach(api "kutlog::Lobe::Lobe(" "kutlog::Lobe::eval_out_of_line(" "kutlog::PerLaneLobe::eval("
            "kutlog::shade(" "kutlog::math::pow_u10(" "kutlog::ref::KutlogLobe::KutlogLobe("
            "kutlog::active_arch()" "kutlog::Lobe::active_loops_"
            # the C API (kutlog/kutlog.h)
            "kutlog_lobe_create" "kutlog_fragment_kernel_eval" "kutlog_shade_directional"
            "kutlog_sampler_sample_array" "kutlog_pow_u10_scalar_y" "kutlog_force_arch")
  string(FIND "${symbols}" "${api}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${LIBRARY} does not export ${api}")
  endif()
endforeach()
# No detail symbol: what the headers' inline code reads is the classes' own.
string(REGEX MATCHALL "[^\n]*kutlog::detail::[^\n]*" internals "${symbols}")
if(internals)
  list(LENGTH internals count)
  list(GET internals 0 first)
  message(FATAL_ERROR "${LIBRARY} exports ${count} internal symbols, such as: ${first}")
endif()
message(STATUS "${LIBRARY}: SONAME set, API exported, no kutlog::detail symbol")
