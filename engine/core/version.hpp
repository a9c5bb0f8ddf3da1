// The code version recorded in every output file's provenance.
#pragma once
#include <string>

namespace softpack {

/// "<release> (<git describe>)", e.g. "0.1.0 (3f2a1bc-dirty)".
std::string code_version();

}  // namespace softpack
