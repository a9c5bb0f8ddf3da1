// The code version recorded in every output file's provenance.
#pragma once
#include <string>

namespace softpack {

/// "<release> (<git describe>)", e.g. "0.2.0 (3f2a1bc-dirty)".
std::string code_version();
/// The release alone, e.g. "0.2.0" (CMakeLists.txt's project version).
std::string release_version();
/// The release of a recorded code version: "0.2.0 (3f2a1bc-dirty)" gives "0.2.0". A change of
/// result bits bumps the release, so a result of another release is not this build's.
std::string release_of(const std::string& code_version);

}  // namespace softpack
