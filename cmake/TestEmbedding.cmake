# Configures Examples/embedding, which pulls HexEx in with add_subdirectory(), in a fresh
# directory with GTest made unfindable and no build type, and with its checks on: the
# subproject must define only the library (and its adapter targets), must not look for
# GTest and must not set the build type.
#
#   cmake -DHEXEX_SOURCE_DIR=<src> -DWORK_DIR=<scratch> [-DGENERATOR=Ninja] [-DCXX_COMPILER=...]
#         [-DEXTRA_PREFIX_PATH=...] -P cmake/TestEmbedding.cmake
cmake_minimum_required(VERSION 3.16)
foreach(var HEXEX_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "TestEmbedding.cmake: pass -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
if(EXTRA_PREFIX_PATH)
  set(ENV{CMAKE_PREFIX_PATH} "${EXTRA_PREFIX_PATH}")
endif()
set(args -S "${HEXEX_SOURCE_DIR}/Examples/embedding" -B "${WORK_DIR}"
  "-DHEXEX_SOURCE_DIR=${HEXEX_SOURCE_DIR}" -DHEXEX_EMBEDDING_CHECKS=ON
  -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON)
if(GENERATOR)
  list(APPEND args -G "${GENERATOR}")
endif()
if(CXX_COMPILER)
  list(APPEND args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the embedding project failed (${rc})")
endif()
if(NOT out MATCHES "embedding check: only the library, no GTest, build type untouched: OK")
  message(FATAL_ERROR "the embedding checks did not run")
endif()
message(STATUS "add_subdirectory(HexEx): OK")
