#include "core/version.hpp"

#include "softpack_version.hpp"

namespace softpack {

std::string code_version() { return std::string(SOFTPACK_VERSION) + " (" + SOFTPACK_GIT + ")"; }

std::string release_version() { return SOFTPACK_VERSION; }

std::string release_of(const std::string& code_version) { return code_version.substr(0, code_version.find(' ')); }

}  // namespace softpack
