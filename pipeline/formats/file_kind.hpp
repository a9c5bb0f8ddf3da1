// Which softpack file an HDF5 file is, so that a reader given the wrong one can say what it got
// ("not a softpack packing file (it is a normal sweep results file (softpack-normal))"). Each
// format module knows its own layout and says whether a file has it (describe_*_file, with
// has_layout); kind_of asks them all.
#pragma once
#include <optional>
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

/// The configuration stamp a result file records (profile/profile.hpp) and the stage it is of: a
/// packing (packing), a sweep's point or results file (its stage), an average file or a fit file
/// (.json; average). nullopt for a file that records none (written before stamps, or by hand
/// without --config), or that cannot be read (its consumer says why). What `make` reruns besides
/// what its stamps say (softpack-config PROFILE stale).
struct RecordedStamp {
  std::string stage, stamp;
};
std::optional<RecordedStamp> recorded_stamp(const std::string& path);

}  // namespace softpack
