// The many-body probe's second part (issue 33, items 1 and 5; paper/many-body.md, "The probe's
// second part", written before its runs): the law chosen on walls tested on other pressing bodies
// (PROBE_DIR/RADIUS/bodies-KIND-S.dat) and the tangential response under confinement
// (PROBE_DIR/RADIUS/shear-S.dat). Nothing here is fitted into the engine's law: β refitted per
// body kind is a diagnosis.
//
// A per-seed ratio X/Y is summarised as its geometric mean over the seeds, exp(m), with m the mean
// of ln(X/Y) and se its standard error; "within" means |m| <= 2 se (the plan's test of ratio 1).
#pragma once
#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "coarse/probe_fit.hpp"

namespace softpack {

struct LogRatio {
  double mean = 0.0, se = 0.0;  ///< of ln(ratio) over the seeds
  std::size_t seeds = 0;
  bool within() const { return seeds > 1 && std::abs(mean) <= 2.0 * se; }
};

/// An error as the reports show it: "exp(rms) (mean of the logarithm)", "–" without points.
std::string error_factor(const ProbeError& e);
nlohmann::json probe_error_json(const ProbeError& e);

/// The curves figures/confined_soft.gp draws of a confined part of the probe: OUT/NAME.dat, a block
/// '# RADIUS RUN' per radius and run of `runs` (NAME:KIND, on the kind's Δn grid) with the first
/// contact's measured force (mean and standard error over the seeds) and each form's prediction
/// predict(form index, point) (the seeds' mean: a stress term has each seed's forces), and its
/// variables OUT/NAME-vars.gp (`body`: what presses, when not a soft-particle).
void write_confined_curves(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& confined, const std::vector<std::string>& runs,
                           const std::vector<std::string>& forms, const std::function<double(std::size_t, const ProbeWallForce&)>& predict,
                           const std::string& title, const std::string& out_dir, const std::string& name, const std::string& body = "");

/// One confined shear point of a file (multi-contact --part shear).
struct ShearRow {
  std::string radius, arrangement;
  std::uint64_t seed = 0;
  double delta_n = 0.0, ht = 0.0, Fn = 0.0, Ft = 0.0;  ///< ht over Rs; [N]
};
/// The rows of PROBE_DIR/RADIUS/shear-S.dat; InputError naming the file and line.
std::vector<ShearRow> read_shear_file(const std::string& path, const std::string& radius, std::uint64_t seed);

struct SecondPart {
  /// 1. The single contact of each kind over the wall's: [kind][radius][Δn].
  std::map<std::string, std::map<std::string, std::map<double, LogRatio>>> single;
  /// 2. Per kind and arrangement of >= 2 contacts: the errors of pairwise (the kind's own F1),
  /// volumetric (the walls' β) and, for soft, the engine's rule (β/2: the two strains' mean).
  struct KindErrors {
    std::map<std::string, ProbeError> pairwise, volumetric, engine;  ///< by arrangement
    double beta = 0.0, beta_se = 0.0;  ///< refitted on this kind's arrangements (a diagnosis)
    bool carries_over = false;         ///< volumetric below pairwise on every arrangement
  };
  std::map<std::string, KindErrors> kinds;
  double beta_walls = 0.0;
  /// 3. The confined shear over `one`'s, per radius, arrangement, Δn.
  struct Shear {
    LogRatio kt, mu, Fn;             ///< kt, the sliding ratio at the largest ht, the first wall's Fn at ht = 0
    double kt_one = 0.0, mu_one = 0.0;  ///< `one`'s, mean over the seeds [N/m], [-]
    double kt_mean = 0.0, mu_mean = 0.0;
  };
  std::map<std::string, std::map<std::string, std::map<double, Shear>>> shear;
  std::vector<std::string> notes;  ///< what could not be computed, and why
};

/// The analysis of the second part; `walls` the seed files', `bodies` the bodies files',
/// `beta` the volumetric β chosen on the walls.
SecondPart analyse_second_part(const ManyBodyProbe& plan, const std::vector<ProbeWallForce>& walls, const std::vector<ProbeWallForce>& bodies,
                               const std::vector<ShearRow>& shear, double beta);

/// The bodies files (PROBE_DIR/RADIUS/bodies-KIND-S.dat) of `kinds` (the plan's body_kinds(), or
/// its confined kinds) and the shear files of the plan.
std::vector<ProbeWallForce> read_bodies_files(const ManyBodyProbe& plan, const std::string& probe_dir, const std::vector<std::string>& kinds);
std::vector<ShearRow> read_shear_files(const ManyBodyProbe& plan, const std::string& probe_dir);

/// Analyses the bodies and shear files' points, writes OUT/second-part.md and OUT/second-part.json.
SecondPart write_second_part(const ManyBodyProbe& plan, const std::string& plan_path, const std::vector<ProbeWallForce>& walls,
                             const std::vector<ProbeWallForce>& bodies, const std::vector<ShearRow>& shear, double beta,
                             const std::string& out_dir);

}  // namespace softpack
