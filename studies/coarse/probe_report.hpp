// The many-body probe's report (issue 33; make many-body-report): the analysis of
// coarse/probe_fit.hpp on every probe file of the plan, written to OUT/probe.md (tables),
// OUT/probe.json (the same numbers, for programs and paper/variables.py) and OUT/probe.dat (each
// arrangement's first wall, measured and predicted, for figures).
#pragma once
#include <string>

#include "coarse/probe_fit.hpp"

namespace softpack {

/// Reads PROBE_DIR/RADIUS/seed-S.dat for every radius and seed of `plan` (InputError naming a
/// missing one), analyses them and writes the three files to `out_dir`; returns the analysis.
ProbeAnalysis write_probe_report(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& probe_dir,
                                 const std::string& out_dir);

}  // namespace softpack
