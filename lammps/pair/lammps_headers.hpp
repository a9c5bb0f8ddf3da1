// LAMMPS's headers as this wing includes them (always through this file). Debian's liblammps carries
// its own fmt (fmt::v7_lmp) and its headers include "fmt/format.h", which is Debian's fmt 9 here; fmt 9
// no longer has make_args_checked, which the headers' variadic message templates name. Those
// templates are never instantiated by this wing (it calls the string overloads only, e.g.
// Error::all(file, line, text)), so a declaration lets the headers compile; no call ever reaches it.
#pragma once
#include <fmt/format.h>

namespace fmt {
template <typename... Args, typename S>
auto make_args_checked(const S&, const Args&... args) {
  return fmt::make_format_args(args...);
}
}  // namespace fmt

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "input.h"
#include "lammps.h"
#include "library.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"
