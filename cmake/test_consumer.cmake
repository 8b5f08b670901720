# CTest driver for the test `consumer_find_package` (run with `cmake -D... -P`):
#   (a) install the package from AF_BUILD_DIR into AF_PREFIX (and run the installed program's --version),
#   (b) configure the consumer project AF_CONSUMER_SOURCE_DIR into AF_CONSUMER_BINARY_DIR with
#       CMAKE_PREFIX_PATH=AF_PREFIX (so only find_package(Anisotropic_fairing) can find it),
#   (c) build it and (d) run its executable. Any failure is fatal.
cmake_minimum_required(VERSION 3.14)

foreach(var AF_BUILD_DIR AF_PREFIX AF_BINDIR AF_CONSUMER_SOURCE_DIR AF_CONSUMER_BINARY_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "test_consumer.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT AF_BUILD_TYPE)
  set(AF_BUILD_TYPE Release)
endif()

function(af_run step)
  message(STATUS "[consumer] ${step}: ${ARGN}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "[consumer] ${step} failed (${rc})")
  endif()
endfunction()

# (a) Install into a fresh prefix, so no stale header survives from an earlier run.
file(REMOVE_RECURSE "${AF_PREFIX}")
af_run("install" "${CMAKE_COMMAND}" --install "${AF_BUILD_DIR}" --prefix "${AF_PREFIX}"
       --config "${AF_BUILD_TYPE}")
# the program is installed too, and runs from there
af_run("installed program" "${AF_PREFIX}/${AF_BINDIR}/anisotropic_fairing" --version)

# (b) Configure. The consumer build dir is kept between runs (incremental), but the package
# location is re-checked every time.
set(config_args
  -S "${AF_CONSUMER_SOURCE_DIR}" -B "${AF_CONSUMER_BINARY_DIR}"
  "-DCMAKE_PREFIX_PATH=${AF_PREFIX}"
  "-DCMAKE_BUILD_TYPE=${AF_BUILD_TYPE}"
  -UAnisotropic_fairing_DIR)
if(AF_GENERATOR AND NOT EXISTS "${AF_CONSUMER_BINARY_DIR}/CMakeCache.txt")
  list(APPEND config_args -G "${AF_GENERATOR}")
endif()
if(AF_CXX_COMPILER)
  list(APPEND config_args "-DCMAKE_CXX_COMPILER=${AF_CXX_COMPILER}")
endif()
af_run("configure" "${CMAKE_COMMAND}" ${config_args})

# Make sure the installed package was used, not something else on the system.
file(STRINGS "${AF_CONSUMER_BINARY_DIR}/CMakeCache.txt" af_dir_line REGEX "^Anisotropic_fairing_DIR:")
string(REGEX REPLACE "^[^=]*=" "" af_dir "${af_dir_line}")
file(REAL_PATH "${AF_PREFIX}" af_prefix_real)
file(REAL_PATH "${af_dir}" af_dir_real)
string(FIND "${af_dir_real}/" "${af_prefix_real}/" pos)
if(NOT pos EQUAL 0)
  message(FATAL_ERROR "[consumer] found Anisotropic_fairing in '${af_dir}', not under '${AF_PREFIX}'")
endif()
message(STATUS "[consumer] Anisotropic_fairing_DIR = ${af_dir}")

# (c) Build.
af_run("build" "${CMAKE_COMMAND}" --build "${AF_CONSUMER_BINARY_DIR}" --config "${AF_BUILD_TYPE}")

# (d) Run.
set(app "${AF_CONSUMER_BINARY_DIR}/app")
if(NOT EXISTS "${app}")
  set(app "${AF_CONSUMER_BINARY_DIR}/${AF_BUILD_TYPE}/app${CMAKE_EXECUTABLE_SUFFIX}")
endif()
af_run("run" "${app}")
message(STATUS "[consumer] OK")
