// What the sweep tests share: the small test profile (tests/data/sweep-profile.yaml, about 60
// grains per soft-particle), its packings, a temporary folder, and a sweep context on them.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

#include "profile/profile.hpp"
#include "measure/sweeps.hpp"
#include "packing/generator.hpp"
#include "packing/packing_profile.hpp"
#include "support/temp_dir.hpp"

namespace softpack::testing {

inline const ConfigNode& sweep_profile() {
  static const ConfigNode root = ConfigNode::load_file(SOFTPACK_SOURCE_DIR "/tests/data/sweep-profile.yaml");
  return root;
}

inline PackingFile sweep_packing(std::uint64_t seed) {
  const PackingProfile prof = parse_packing(sweep_profile());
  const Packing p = generate_packing(prof.parameters, seed);
  PackingFile f;
  f.centres = p.centres;
  f.radii = p.radii;
  f.Rs = prof.parameters.Rs;
  f.parameters = prof.parameters;
  f.provenance.seed = seed;
  return f;
}

inline SweepContext sweep_context(const ContactSetup& setup, const std::string& dir) {
  SweepContext c;
  c.setup = setup;
  c.settings = parse_measurement(sweep_profile());
  c.config = "test";
  c.normal_config = c.config;  // one context for the normal sweep and the sweeps from its states
  c.checkpoint_dir = dir;
  c.code_version = "test";
  return c;
}

}  // namespace softpack::testing
