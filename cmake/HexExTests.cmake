# Tests of the project as a package, added to ctest next to the GoogleTest suite.
# Included from the top-level CMakeLists.txt after all targets exist.

# Install into a scratch prefix and build + run Examples/minimal with find_package(HexEx).
set(_hexex_test_flags "")
if(HEXEX_SANITIZE)
  # The installed static library carries sanitizer instrumentation; the consumer must link the runtimes.
  set(_hexex_test_flags "-fsanitize=address,undefined")
endif()
# One test per example: install into its own scratch prefix (so the tests may run in
# parallel), then configure, build and run the example against find_package(HexEx).
function(hexex_add_install_test name example_dir program)
  set(extra_prefix "${ARGN}")
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND}
      -DHEXEX_BINARY_DIR=${PROJECT_BINARY_DIR}
      -DEXAMPLE_SOURCE_DIR=${PROJECT_SOURCE_DIR}/Examples/${example_dir}
      -DEXAMPLE_PROGRAM=${program}
      -DWORK_DIR=${PROJECT_BINARY_DIR}/test-${name}
      -DGENERATOR=${CMAKE_GENERATOR}
      -DBUILD_TYPE=$<CONFIG>
      -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
      -DEXTRA_CXX_FLAGS=${_hexex_test_flags}
      -DEXTRA_LINKER_FLAGS=${_hexex_test_flags}
      "-DEXTRA_PREFIX_PATH=${extra_prefix}"
      -P ${PROJECT_SOURCE_DIR}/cmake/TestInstall.cmake)
  set_tests_properties(${name} PROPERTIES TIMEOUT 600 LABELS package)
endfunction()

# Examples/minimal extracts a generated cube; Examples/traits reads and writes a
# user-defined mesh kernel through the mesh-kernel traits (HexEx/HexExTraits.hh).
hexex_add_install_test(install_and_find_package minimal app)
hexex_add_install_test(install_and_find_package_traits traits traits)
# The adapters: Examples/cgal_lcc (CGAL is a dependency, always built) and
# Examples/openvolumemesh (only when OpenVolumeMesh is found; its prefix is passed on).
hexex_add_install_test(install_and_find_package_cgal_lcc cgal_lcc cgal_lcc)
# The C API: Examples/c_api builds a C99 program against HexEx::C and the installed hexex.h.
if(TARGET hexex_c)
  hexex_add_install_test(install_and_find_package_c_api c_api extract_c)
endif()
include(${PROJECT_SOURCE_DIR}/cmake/HexExOpenVolumeMesh.cmake)
if(OpenVolumeMesh_FOUND)
  # <prefix>/lib/cmake/OpenVolumeMesh -> <prefix>
  get_filename_component(_hexex_ovm_prefix "${OpenVolumeMesh_DIR}/../../.." ABSOLUTE)
  hexex_add_install_test(install_and_find_package_openvolumemesh openvolumemesh openvolumemesh ${_hexex_ovm_prefix})
endif()

# add_subdirectory() of the project: only the library, no GTest, no forced build type
# (configured, not built: Examples/embedding, cmake/TestEmbedding.cmake).
add_test(NAME embed_with_add_subdirectory
  COMMAND ${CMAKE_COMMAND}
    -DHEXEX_SOURCE_DIR=${PROJECT_SOURCE_DIR}
    -DWORK_DIR=${PROJECT_BINARY_DIR}/test-embed_with_add_subdirectory
    -DGENERATOR=${CMAKE_GENERATOR}
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
    "-DEXTRA_PREFIX_PATH=${CMAKE_PREFIX_PATH}"
    -P ${PROJECT_SOURCE_DIR}/cmake/TestEmbedding.cmake)
set_tests_properties(embed_with_add_subdirectory PROPERTIES TIMEOUT 300 LABELS package)

# The API documentation must build without a single Doxygen warning.
if(TARGET doc)
  add_test(NAME doxygen_docs COMMAND ${CMAKE_COMMAND} --build ${PROJECT_BINARY_DIR} --target doc)
  set_tests_properties(doxygen_docs PROPERTIES TIMEOUT 300 LABELS docs)
endif()
