# Tests of the project as a package, added to ctest next to the GoogleTest suite.
# Included from the top-level CMakeLists.txt after all targets exist.

# Install into a scratch prefix and build + run Examples/minimal with find_package(HexEx).
set(_hexex_test_flags "")
if(HEXEX_SANITIZE)
  # The installed static library carries sanitizer instrumentation; the consumer must link the runtimes.
  set(_hexex_test_flags "-fsanitize=address,undefined")
endif()
add_test(NAME install_and_find_package
  COMMAND ${CMAKE_COMMAND}
    -DHEXEX_BINARY_DIR=${PROJECT_BINARY_DIR}
    -DEXAMPLE_SOURCE_DIR=${PROJECT_SOURCE_DIR}/Examples/minimal
    -DWORK_DIR=${PROJECT_BINARY_DIR}/test-install
    -DGENERATOR=${CMAKE_GENERATOR}
    -DBUILD_TYPE=$<CONFIG>
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
    -DEXTRA_CXX_FLAGS=${_hexex_test_flags}
    -DEXTRA_LINKER_FLAGS=${_hexex_test_flags}
    -P ${PROJECT_SOURCE_DIR}/cmake/TestInstall.cmake)
set_tests_properties(install_and_find_package PROPERTIES TIMEOUT 600 LABELS package)

# The same for Examples/traits: a user-defined mesh kernel read and written through the
# mesh-kernel traits (HexEx/HexExTraits.hh). Own scratch prefix, so it may run in parallel.
add_test(NAME install_and_find_package_traits
  COMMAND ${CMAKE_COMMAND}
    -DHEXEX_BINARY_DIR=${PROJECT_BINARY_DIR}
    -DEXAMPLE_SOURCE_DIR=${PROJECT_SOURCE_DIR}/Examples/traits
    -DEXAMPLE_PROGRAM=traits
    -DWORK_DIR=${PROJECT_BINARY_DIR}/test-install-traits
    -DGENERATOR=${CMAKE_GENERATOR}
    -DBUILD_TYPE=$<CONFIG>
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
    -DEXTRA_CXX_FLAGS=${_hexex_test_flags}
    -DEXTRA_LINKER_FLAGS=${_hexex_test_flags}
    -P ${PROJECT_SOURCE_DIR}/cmake/TestInstall.cmake)
set_tests_properties(install_and_find_package_traits PROPERTIES TIMEOUT 600 LABELS package)

# The API documentation must build without a single Doxygen warning.
if(TARGET doc)
  add_test(NAME doxygen_docs COMMAND ${CMAKE_COMMAND} --build ${PROJECT_BINARY_DIR} --target doc)
  set_tests_properties(doxygen_docs PROPERTIES TIMEOUT 300 LABELS docs)
endif()
