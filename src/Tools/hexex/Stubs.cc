// Temporary stubs; each subcommand gets its own file (InfoCommand.cc, ...) that replaces one line here.
#include "Commands.hh"
#include <iostream>
namespace HexExTool {
}
