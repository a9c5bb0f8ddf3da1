// The code version recorded in every output file's provenance.
#pragma once
#include <string>

namespace softpack {

/// "<release> (<git describe>)", e.g. "0.2.0 (3f2a1bc-dirty)".
std::string code_version();
/// The release alone, e.g. "0.2.0" (CMakeLists.txt's project version).
std::string release_version();

}  // namespace softpack
