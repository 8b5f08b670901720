# Compiles SOURCE (-fsyntax-only) and passes when the compiler reports exactly one error and it contains
# EXPECTED: a user's mistake gets one sentence, not pages of template errors.
# cmake -DCXX=... -DSOURCE=... -DINCLUDES="dir;dir" -DEXPECTED="text" -P compile_error_test.cmake
set(flags -std=c++17 -fsyntax-only)
foreach(dir ${INCLUDES})
  list(APPEND flags -I${dir})
endforeach()
execute_process(COMMAND ${CXX} ${flags} ${SOURCE} RESULT_VARIABLE result ERROR_VARIABLE output OUTPUT_VARIABLE output)
if(result EQUAL 0)
  message(FATAL_ERROR "${SOURCE} compiled, but it must not")
endif()
string(REGEX MATCHALL "error:" errors "${output}")
list(LENGTH errors count)
string(FIND "${output}" "${EXPECTED}" at)
if(NOT count EQUAL 1 OR at EQUAL -1)
  message(FATAL_ERROR "expected exactly one error containing '${EXPECTED}', got ${count}:\n${output}")
endif()
message(STATUS "one error, as expected: ${EXPECTED}")
