# cmake -DLIBRARY=<libkutlog.so> -P shared_exports.cmake
# The shared library carries its SONAME and exports the API, not its internals.
execute_process(COMMAND objdump -p ${LIBRARY} OUTPUT_VARIABLE headers COMMAND_ERROR_IS_FATAL ANY)
if(NOT headers MATCHES "SONAME +libkutlog\\.so\\.[0-9]+")
  message(FATAL_ERROR "${LIBRARY} has no SONAME libkutlog.so.<major>")
endif()
execute_process(COMMAND nm -DC --defined-only ${LIBRARY} OUTPUT_VARIABLE symbols
                COMMAND_ERROR_IS_FATAL ANY)
foreach(api "kutlog::Lobe::Lobe(" "kutlog::Lobe::eval(" "kutlog::shade(" "kutlog::math::pow_u10("
            "kutlog::ref::KutlogLobe::KutlogLobe(" "kutlog::active_arch()")
  string(FIND "${symbols}" "${api}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${LIBRARY} does not export ${api}")
  endif()
endforeach()
string(REGEX MATCHALL "[^\n]*kutlog::detail::[^\n]*" internals "${symbols}")
if(internals)
  list(LENGTH internals count)
  list(GET internals 0 first)
  message(FATAL_ERROR "${LIBRARY} exports ${count} internal symbols, such as: ${first}")
endif()
message(STATUS "${LIBRARY}: SONAME set, API exported, no kutlog::detail symbol")
