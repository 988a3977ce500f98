# cmake -DCOMPILER=<c++> "-DFLAGS=<flags;...>" "-DINCLUDES=<dir;...>" -DLIBRARY=<libkutlog.a>
#   -DSOURCE=<footprint.cpp> -DBINARY=<work dir> -DNM=<nm> -DSIZE=<size> -DARCHS=<count>
#   -DLIMIT=<bytes, or empty: no limit> ["-DEMULATOR=<command;...>"] -P footprint.cmake
# Links footprint.cpp's programs (and footprint.c's, the same through the C API) statically
# against libkutlog.a, as a renderer would, with and without --gc-sections. The one whose only
# kutlog calls are Lobe's setup and scalar eval, in C++ or C, must
# link no kernel table and at most LIMIT bytes of kutlog (its text and data less those of the
# same loops with std::pow). Those that also call the array eval or read the SIMD kernels
# (kutlog/inspect.hpp) must link every arch's table and find the SIMD kernels fitted; all give
# the same scalar outputs.
file(MAKE_DIRECTORY ${BINARY})
list(TRANSFORM INCLUDES PREPEND -I)

# Builds the program of that variant (the suffix of a footprint.cpp macro).
# C: footprint.c, the scalar program through the C API, compiled as C99 and linked with what
# kutlog.pc's Libs.private names.
function(build_program program variant link_flags)
  set(source -std=c++20 ${SOURCE})
  if(variant STREQUAL "C")
    get_filename_component(directory ${SOURCE} DIRECTORY)
    set(source -x c -std=c99 ${directory}/footprint.c -x none)
    set(runtime -lstdc++ -lm)
  endif()
  # One contraction for both languages: GCC fuses a * b + c in C++ by default (on FMA targets),
  # not in ISO C, and the inline eval's last bits follow.
  execute_process(COMMAND ${COMPILER} -O2 -ffp-contract=off ${FLAGS}
                          -DKUTLOG_FOOTPRINT_${variant} ${INCLUDES} ${source} ${LIBRARY} ${runtime}
                          ${link_flags} -o ${program}
                  COMMAND_ERROR_IS_FATAL ANY)
endfunction()

# Its text and data, in bytes (`size`, Berkeley format).
function(measure out_var program)
  execute_process(COMMAND ${SIZE} ${program} OUTPUT_VARIABLE table COMMAND_ERROR_IS_FATAL ANY)
  string(REGEX MATCH "\n *([0-9]+)[ \t]+([0-9]+)" row "${table}")
  math(EXPR bytes "${CMAKE_MATCH_1} + ${CMAKE_MATCH_2}")
  set(${out_var} ${bytes} PARENT_SCOPE)
endfunction()

# How many kernel tables (detail::kernel_table<Arch>()) it defines.
function(count_tables out_var program)
  execute_process(COMMAND ${NM} -C ${program} OUTPUT_VARIABLE symbols COMMAND_ERROR_IS_FATAL ANY)
  string(REGEX MATCHALL "[^\n]* kutlog::detail::kernel_table<[^>\n]*>\\(\\)\n" tables
         "${symbols}")
  list(LENGTH tables count)
  set(${out_var} ${count} PARENT_SCOPE)
endfunction()

# Its output, the scalar digest; fatal if it fails.
function(run out_var program)
  execute_process(COMMAND ${EMULATOR} ${program} RESULT_VARIABLE status OUTPUT_VARIABLE output
                  ERROR_VARIABLE output OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${program}: ${status}\n${output}")
  endif()
  set(${out_var} "${output}" PARENT_SCOPE)
endfunction()

foreach(link_flags "" "-Wl,--gc-sections")
  set(linked "linked")
  if(link_flags)
    set(linked "linked with --gc-sections")
  endif()
  build_program(${BINARY}/pow${link_flags} POW "${link_flags}")
  measure(pow_bytes ${BINARY}/pow${link_flags})
  foreach(variant SCALAR C ARRAY INSPECT)
    set(program ${BINARY}/${variant}${link_flags})
    build_program(${program} ${variant} "${link_flags}")
    measure(bytes ${program})
    math(EXPR kutlog_bytes "${bytes} - ${pow_bytes}")
    count_tables(tables ${program})
    message(STATUS "${variant} ${linked}: ${kutlog_bytes} bytes of kutlog, ${tables} kernel tables")
    if(variant MATCHES "^(SCALAR|C)$")
      if((LIMIT AND kutlog_bytes GREATER LIMIT) OR NOT tables EQUAL 0)
        message(FATAL_ERROR "Lobe's scalar eval alone (${variant}) links ${kutlog_bytes} bytes "
                            "of kutlog (at most ${LIMIT}) and ${tables} kernel tables (none)")
      endif()
    elseif(NOT tables EQUAL ARCHS)
      message(FATAL_ERROR "${variant} links ${tables} kernel tables, not every arch's ${ARCHS}")
    endif()
    run(output ${program})
    if(variant STREQUAL "SCALAR")
      set(scalar_output "${output}")
    elseif(NOT output STREQUAL scalar_output)
      message(FATAL_ERROR "the scalar eval's outputs depend on what else is linked: "
                          "'${scalar_output}' alone, '${output}' in ${variant}")
    endif()
  endforeach()
endforeach()
