// What the validators of scene/validate.hpp share (scene/validate.cpp, validate_relaxation.cpp):
// the refusal and the range check, each naming the key.
#pragma once
#include <string>

#include "core/error.hpp"
#include "scene/limits.hpp"

namespace softpack::validation {

[[noreturn]] inline void fail(const std::string& key, const std::string& what) { throw InputError(key + ": " + what); }

/// A range of scene/limits.hpp: "<key>: <v> <unit> is not allowed; allowed: <range>".
inline void check(const std::string& key, double v, const limits::Range& range) {
  if (const std::string why = limits::refusal(v, range); !why.empty()) fail(key, why);
}

}  // namespace softpack::validation
