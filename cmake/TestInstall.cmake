# Installs a built HexEx into a scratch prefix, then configures, builds and runs a
# standalone example (Examples/minimal, Examples/traits) against it with find_package(HexEx).
#
#   cmake -DHEXEX_BINARY_DIR=<build> -DEXAMPLE_SOURCE_DIR=<Examples/minimal>
#         -DWORK_DIR=<scratch dir> [-DEXAMPLE_PROGRAM=app] [-DGENERATOR=Ninja] [-DBUILD_TYPE=Release]
#         [-DCXX_COMPILER=...] [-DEXTRA_CXX_FLAGS=...] [-DEXTRA_LINKER_FLAGS=...]
#         [-DEXTRA_PREFIX_PATH=<another prefix searched by the example, e.g. OpenVolumeMesh's>]
#         -P cmake/TestInstall.cmake
#
# Every step's output is shown; the first failing step ends the script with an error.
cmake_minimum_required(VERSION 3.16)

foreach(var HEXEX_BINARY_DIR EXAMPLE_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "TestInstall.cmake: pass -D${var}=...")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()
if(NOT EXAMPLE_PROGRAM)
  set(EXAMPLE_PROGRAM app)
endif()

set(prefix "${WORK_DIR}/prefix")
set(example_build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(run_step name)
  message(STATUS "[${name}] ${ARGN}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "[${name}] failed (${rc})")
  endif()
endfunction()

run_step(install "${CMAKE_COMMAND}" --install "${HEXEX_BINARY_DIR}" --prefix "${prefix}" --config "${BUILD_TYPE}")

if(EXTRA_PREFIX_PATH)
  # Through the environment: a ';' list would split the -D argument.
  set(ENV{CMAKE_PREFIX_PATH} "${EXTRA_PREFIX_PATH}")
endif()
set(configure_args -S "${EXAMPLE_SOURCE_DIR}" -B "${example_build}"
  "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
if(GENERATOR)
  list(APPEND configure_args -G "${GENERATOR}")
endif()
if(CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
if(EXTRA_CXX_FLAGS)
  list(APPEND configure_args "-DCMAKE_CXX_FLAGS=${EXTRA_CXX_FLAGS}")
endif()
if(EXTRA_LINKER_FLAGS)
  list(APPEND configure_args "-DCMAKE_EXE_LINKER_FLAGS=${EXTRA_LINKER_FLAGS}")
endif()
run_step(configure "${CMAKE_COMMAND}" ${configure_args})
run_step(build "${CMAKE_COMMAND}" --build "${example_build}" --config "${BUILD_TYPE}")

# Single- and multi-config generators put the program in different places.
find_program(example_exe NAMES ${EXAMPLE_PROGRAM} PATHS "${example_build}" "${example_build}/${BUILD_TYPE}"
  NO_DEFAULT_PATH)
if(NOT example_exe)
  message(FATAL_ERROR "[run] the example program was not built")
endif()
run_step(run "${example_exe}")
message(STATUS "install + find_package(HexEx) + link + run: OK")
