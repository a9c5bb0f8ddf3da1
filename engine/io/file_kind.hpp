// Which softpack file an HDF5 file is, so that a reader given the wrong one can say what it got
// ("not a softpack packing file (it is a normal sweep results file)"). Kept out of the generic
// HDF5 layer (io/hdf5_file.hpp): it knows the layouts of the project's files.
#pragma once
#include <string>

#include "io/hdf5_file.hpp"

namespace softpack::h5 {

/// What a softpack file is, from its layout: "a packing file (softpack-pack)", "a sweep point
/// file (a checkpoint of softpack-normal or softpack-tangential)", "a normal sweep results file
/// (softpack-normal)", "an average file (softpack-average)", ...; "" for any other HDF5 file.
/// Readers use it to say what a file given in the wrong place is.
std::string kind_of(const File& f);

}  // namespace softpack::h5
