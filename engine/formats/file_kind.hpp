// Which softpack file an HDF5 file is, so that a reader given the wrong one can say what it got
// ("not a softpack packing file (it is a normal sweep results file (softpack-normal))"). Each
// format module knows its own layout and says whether a file has it (describe_*_file, with
// has_layout); kind_of asks them all.
#pragma once
#include <span>
#include <string>

#include "io/hdf5_file.hpp"

namespace softpack {

/// What a softpack file is: "a packing file (softpack-pack)", "a sweep point file (a checkpoint
/// of softpack-normal)", "a normal sweep results file (softpack-normal)", "an average file
/// (softpack-average)", ...; "" for any other HDF5 file.
std::string kind_of(const h5::File& f);

/// True when every path of `layout` (the datasets that make a file of one kind) exists in `f`.
bool has_layout(const h5::File& f, std::span<const char* const> layout);

/// InputError "<file>: not a softpack <what> file (no /a, /b or /c)", or "(it is <kind_of>)"
/// for another softpack file, unless `f` has `layout`.
void expect_layout(const h5::File& f, const std::string& what, std::span<const char* const> layout);

}  // namespace softpack
