# Runs an example with command-line arguments and checks its exit code and output. Invoked by ctest as
#
#   cmake -DEXE=<path> "-DARGS=<arg;arg;...>" -DEXPECT_FAILURE=<ON|OFF> "-DREGEX=<regular expression>"
#         -P run_example_expecting.cmake
#
# EXPECT_FAILURE ON: the exit code must be non-zero and stderr exactly one line starting with "error:";
# OFF: the exit code must be 0. In both cases stdout and stderr together must match REGEX.
foreach(var EXE REGEX)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_example_expecting.cmake: ${var} is not set")
  endif()
endforeach()
execute_process(COMMAND "${EXE}" ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(EXPECT_FAILURE)
  if(rc EQUAL 0 OR NOT rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "expected a clean failure, got exit code '${rc}'\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(NOT err MATCHES "^error: [^\n]*\n$")
    message(FATAL_ERROR "expected one 'error:' line on stderr, got:\n${err}")
  endif()
elseif(NOT rc EQUAL 0)
  message(FATAL_ERROR "expected exit code 0, got '${rc}'\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(NOT "${out}${err}" MATCHES "${REGEX}")
  message(FATAL_ERROR "output does not match '${REGEX}'\nstdout:\n${out}\nstderr:\n${err}")
endif()
