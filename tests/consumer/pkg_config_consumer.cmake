# cmake -DPREFIX=<install prefix> -DSOURCE=<this directory> -DBINARY=<work dir> [-DSHARED=ON]
#   -P pkg_config_consumer.cmake
# Builds main.cpp, renderer.cpp and c/c_consumer.c as a Make or Meson user would, with the flags
# `pkg-config --cflags --libs kutlog` gives for the installed package, then runs them.
find_program(PKG_CONFIG NAMES pkg-config pkgconf REQUIRED)
file(GLOB_RECURSE pc_files ${PREFIX}/*/kutlog.pc)
list(GET pc_files 0 pc_file)
get_filename_component(pc_dir ${pc_file} DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})
execute_process(COMMAND ${PKG_CONFIG} --cflags --libs kutlog OUTPUT_VARIABLE flags
                OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
message(STATUS "pkg-config --cflags --libs kutlog: ${flags}")
separate_arguments(flags UNIX_COMMAND ${flags})
set(extra)
if(SHARED)  # the loader must find libkutlog.so where it was installed
  string(REGEX MATCH "-L([^;]+)" libdir_flag "${flags}")
  list(APPEND extra -Wl,-rpath,${CMAKE_MATCH_1})
endif()
file(MAKE_DIRECTORY ${BINARY})
execute_process(COMMAND c++ -std=c++20 -O2 ${SOURCE}/main.cpp ${flags} ${extra}
                        -o ${BINARY}/kutlog-consumer COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${BINARY}/kutlog-consumer COMMAND_ERROR_IS_FATAL ANY)

# c/c_consumer.c as C99, linked by the C compiler: the static library through
# `pkg-config --libs --static kutlog`, the shared one through `pkg-config --libs kutlog`.
set(static_flag --static)
if(SHARED)
  set(static_flag)
endif()
execute_process(COMMAND ${PKG_CONFIG} --cflags --libs ${static_flag} kutlog OUTPUT_VARIABLE c_flags
                OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
message(STATUS "pkg-config --cflags --libs ${static_flag} kutlog: ${c_flags}")
separate_arguments(c_flags UNIX_COMMAND ${c_flags})
execute_process(COMMAND cc -std=c99 -Wall -Wextra -pedantic -Werror -O2 ${SOURCE}/c/c_consumer.c
                        ${c_flags} ${extra} -o ${BINARY}/kutlog-c-consumer
                COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${BINARY}/kutlog-c-consumer OUTPUT_VARIABLE c_output
                COMMAND_ERROR_IS_FATAL ANY)
if(NOT c_output MATCHES "c consumer: ok")
  message(FATAL_ERROR "kutlog-c-consumer: ${c_output}")
endif()

# renderer.cpp, with kutlog.pc's flags alone and -fno-exceptions: no header it includes,
# directly or through kutlog's, may be xsimd's (kutlog-simd.pc is the one that requires it).
execute_process(COMMAND ${PKG_CONFIG} --print-requires kutlog OUTPUT_VARIABLE requires
                COMMAND_ERROR_IS_FATAL ANY)
if(requires MATCHES "xsimd")
  message(FATAL_ERROR "kutlog.pc requires xsimd: ${requires}")
endif()
execute_process(COMMAND c++ -std=c++20 -M ${SOURCE}/renderer.cpp ${flags}
                OUTPUT_VARIABLE renderer_headers COMMAND_ERROR_IS_FATAL ANY)
if(renderer_headers MATCHES "[^ ]*xsimd[^ ]*")
  message(FATAL_ERROR "renderer.cpp includes ${CMAKE_MATCH_0} through kutlog's headers")
endif()
# The same for every installed header outside kutlog/simd/.
file(GLOB public_headers RELATIVE ${PREFIX}/include ${PREFIX}/include/kutlog/*.hpp)
list(TRANSFORM public_headers REPLACE "(.+)" "#include <\\1>\n")
file(WRITE ${BINARY}/public_headers.cpp ${public_headers})
execute_process(COMMAND c++ -std=c++20 -M ${BINARY}/public_headers.cpp ${flags}
                OUTPUT_VARIABLE public_dependencies COMMAND_ERROR_IS_FATAL ANY)
if(public_dependencies MATCHES "[^ ]*xsimd[^ ]*")
  message(FATAL_ERROR "a header outside kutlog/simd/ includes ${CMAKE_MATCH_0}")
endif()
execute_process(COMMAND c++ -std=c++20 -O2 -fno-exceptions ${SOURCE}/renderer.cpp ${flags}
                        ${extra} -o ${BINARY}/kutlog-renderer-consumer COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${BINARY}/kutlog-renderer-consumer COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${PKG_CONFIG} --cflags kutlog-simd OUTPUT_VARIABLE simd_flags
                COMMAND_ERROR_IS_FATAL ANY)
message(STATUS "pkg-config --cflags kutlog-simd: ${simd_flags}")
