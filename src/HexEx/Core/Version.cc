#include "Version.hh"

#ifndef HEXEX_VERSION_STRING
#error "HEXEX_VERSION_STRING is set by CMakeLists.txt from the project() version"
#endif

namespace HexEx {

const char* version() { return HEXEX_VERSION_STRING; }

} // namespace HexEx
