#include "core/version.hpp"

#include "softpack_version.hpp"

namespace softpack {

std::string code_version() { return std::string(SOFTPACK_VERSION) + " (" + SOFTPACK_GIT + ")"; }

std::string release_version() { return SOFTPACK_VERSION; }

}  // namespace softpack
