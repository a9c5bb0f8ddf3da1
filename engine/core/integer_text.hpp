// Integers as they are written in configuration files and on command lines, read exactly: an
// optional '-', then decimal digits without a leading zero ("0" itself is one, "-0" is not), and nothing
// else: no '+', no space, no point or exponent (1.0, 1e3), no 0x/0o prefix, no separator. A
// reader through a double would round above 2^53 and clamp or wrap above 2^63; a leading zero
// is octal in YAML 1.1 (010 = 8) and would name another file (seed-01.h5) than the value read.
#pragma once
#include <cstdint>
#include <limits>
#include <string_view>

namespace softpack {

struct IntegerText {
  enum class Status { ok, not_integer, out_of_range } status = Status::not_integer;
  std::int64_t value = 0;  ///< when ok
};

/// Reads `text` by the rules above; out_of_range when it has that form but is beyond the range
/// of std::int64_t (more than 9223372036854775807 in magnitude, -9223372036854775808 aside).
constexpr IntegerText parse_integer(std::string_view text) {
  IntegerText out;
  const bool negative = !text.empty() && text.front() == '-';
  const std::string_view digits = negative ? text.substr(1) : text;
  if (digits.empty() || (digits.front() == '0' && (digits.size() > 1 || negative))) return out;  // 007, -0
  // Accumulated as a negative number: the range of int64 is one wider below zero.
  std::int64_t v = 0;
  constexpr std::int64_t lowest = std::numeric_limits<std::int64_t>::lowest();
  bool overflow = false;
  for (const char c : digits) {
    if (c < '0' || c > '9') return out;
    const int d = c - '0';
    if (v < (lowest + d) / 10) overflow = true;
    if (!overflow) v = v * 10 - d;
  }
  if (overflow || (!negative && v == lowest)) {
    out.status = IntegerText::Status::out_of_range;
    return out;
  }
  out.status = IntegerText::Status::ok;
  out.value = negative ? v : -v;
  return out;
}

}  // namespace softpack
