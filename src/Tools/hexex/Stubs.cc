// Temporary stubs; each subcommand gets its own file (InfoCommand.cc, ...) that replaces one line here.
#include "Commands.hh"
#include <iostream>
namespace HexExTool {
int runExtract(const Args&) { std::cerr << "not implemented\n"; return 2; }
int runValidate(const Args&) { std::cerr << "not implemented\n"; return 2; }
}
