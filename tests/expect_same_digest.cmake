# cmake "-DFIRST=<command>;<args>" "-DSECOND=<command>;<args>" -P expect_same_digest.cmake
# Runs both commands and fails unless each prints a line "image digest: <hex>" and the two
# digests are equal.
foreach(run FIRST SECOND)
  execute_process(COMMAND ${${run}} OUTPUT_VARIABLE output COMMAND_ERROR_IS_FATAL ANY)
  if(NOT output MATCHES "image digest: ([0-9a-f]+)")
    message(FATAL_ERROR "no image digest from ${${run}}:\n${output}")
  endif()
  set(digest_${run} ${CMAKE_MATCH_1})
endforeach()
if(NOT digest_FIRST STREQUAL digest_SECOND)
  message(FATAL_ERROR "different images: ${digest_FIRST} (${FIRST}) and ${digest_SECOND} (${SECOND})")
endif()
message(STATUS "the same image: digest ${digest_FIRST}")
