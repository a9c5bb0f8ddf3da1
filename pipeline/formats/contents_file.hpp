// The contents of a level packing's sites, made once and kept (issue 35; docs/nested.md, "What
// making the contents costs"). A soft-particle with nested content weighs everything inside it,
// and the resolved form places it, so every scene of a nested measurement needs its sites'
// contents down to the last level (packing/nested.hpp generate_contents): at the chain's level 0
// about 700 level packings, about 18 CPU-min, for every stage of every seed and scene. They are
// made by the first scene that needs them and kept beside the packing file, and every later
// scene reads them.
//
//   <packing>.contents.h5   (written atomically; HDF5; <packing>.contents.h5.lock: its maker's lock)
//     key/packing_sha256    SHA-256 of the packing file's bytes: the contents are those of
//                           exactly this packing (its parameters, seed, sites and generator)
//     key/levels_below      the packing's levels - 1
//     key/sites             its sites
//     nodes/*               the contents in pre-order (a site's level packing, then its sites'
//                           contents), one entry per level packing: children, grains, sites,
//                           site_radius, sampled, discarded, grown, sites_drawn, sites_discarded
//     grains/{centres, radii, radii_inserted}, sites/centres   every node's, concatenated
//     provenance/code_version
//
// A file of another key, or one that cannot be read, is made again: it is a copy of what the
// seeds give, never a result of its own.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "formats/packing_file.hpp"
#include "packing/nested.hpp"

namespace softpack {

/// The contents of the sites of `p`, bit for bit generate_contents(p.parameters, levels - 1,
/// seed, sites): read from p.path + ".contents.h5" when it holds this packing's, else made and
/// written there (made only, when `p` was not read from a file), with a line per site made and
/// the time left on the standard error. Processes that need them at once make them once: the
/// first holds `<cache>.lock` (io/file_lock.hpp) while it makes them, the others wait and read
/// them. A packing without levels has none.
std::vector<SiteContent> packing_contents(const PackingFile& p);

/// The file's contents when its key is `packing_sha256`, `levels_below` and `sites`; empty
/// optional when the file is missing, of another key, or cannot be read.
std::optional<std::vector<SiteContent>> read_contents_file(const std::string& path, const std::string& packing_sha256,
                                                           int levels_below, std::size_t sites);
void write_contents_file(const std::string& path, const std::string& packing_sha256, int levels_below,
                         const std::vector<SiteContent>& contents);

}  // namespace softpack
