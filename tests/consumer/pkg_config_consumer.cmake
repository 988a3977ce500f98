# cmake -DPREFIX=<install prefix> -DSOURCE=<this directory> -DBINARY=<work dir> [-DSHARED=ON]
#   -P pkg_config_consumer.cmake
# Builds main.cpp as a Make or Meson user would, with the flags `pkg-config --cflags --libs
# kutlog` gives for the installed package, then runs it.
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
