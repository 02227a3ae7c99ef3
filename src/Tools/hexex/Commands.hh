#pragma once
/// @file Commands.hh
/// Subcommands of the hexex tool. Each returns the process exit status:
/// 0 success, 2 bad input or usage, 3 output written but not all-hex.

#include <string>
#include <vector>

namespace HexExTool {

/// Arguments after the subcommand name.
using Args = std::vector<std::string>;

int runInfo(const Args& args);      ///< hexex info IN [--json]
int runExtract(const Args& args);   ///< hexex extract IN -o OUT [...]
int runGenerate(const Args& args);  ///< hexex generate SHAPE [...] -o OUT.hexex
int runPerturb(const Args& args);   ///< hexex perturb IN -a A --seed S -o OUT.hexex
int runValidate(const Args& args);  ///< hexex validate MESH [--json]
int runQuad(const Args& args);      ///< hexex quad IN.obj -o OUT [...] (2D: quad mesh extraction)
int runGenerate2D(const Args& args);  ///< hexex generate square|cone-disk|torus|quarter-seam [...] -o OUT.obj

/// True for the names of the 2D shapes of `hexex generate`.
bool isShape2D(const std::string& name);

/// `hexex perturb` on a 2D map (OBJ with `vt`): perturbs @p input by amplitude @p a with
/// @p seed and writes @p output (OBJ).
int runPerturb2D(const std::string& input, const std::string& output, double a, unsigned seed, bool quiet);
int runConvert(const Args& args);   ///< hexex convert IN OUT [--encoding E]
int runUntangle(const Args& args);  ///< hexex untangle HEX -o OUT [--surface-from MAP] [...]
int runOptimize(const Args& args);  ///< hexex optimize HEX -o OUT [--surface TRI | --surface-from MAP] [...]

} // namespace HexExTool
