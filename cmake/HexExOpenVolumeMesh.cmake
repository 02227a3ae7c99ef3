# Optional OpenVolumeMesh (for the adapter tests, example and benchmark): sets
# OpenVolumeMesh_FOUND and HEXEX_OVM_INCLUDE_DIR. The export of OpenVolumeMesh 3.4.1 gives
# its imported target no include directory, so consumers add HEXEX_OVM_INCLUDE_DIR themselves.
find_package(OpenVolumeMesh CONFIG QUIET)
if(OpenVolumeMesh_FOUND)
  find_path(HEXEX_OVM_INCLUDE_DIR OpenVolumeMesh/Core/Handles.hh HINTS "${OpenVolumeMesh_DIR}/../../../include")
  if(NOT HEXEX_OVM_INCLUDE_DIR)
    message(STATUS "OpenVolumeMesh found at ${OpenVolumeMesh_DIR} but not its headers: treated as not found")
    set(OpenVolumeMesh_FOUND FALSE)
  endif()
endif()
