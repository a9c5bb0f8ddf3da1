// The verdict against the paper (experiments/criteria.yaml `tolerances` and `table2_unit`,
// paper/preregistration.md): one source for the report's verdict table and the regression tests.
//
// Per coefficient: ours ± error, the paper's, the relative deviation, the tolerance and whether
// it is met. Table 2's unit by the preregistered rule: q of every reading per scene
// (analysis/kt_unit.hpp), the reading selected on select_scene (|ln q| least) and tested on
// test_scene (|ln q| <= ln test_factor); Table 2's a is judged in that reading if the test passes,
// else it is "unit undetermined". Beside the verdict, per scene: the joint distance of (a, b, c)
// from the paper's under the jackknife covariance (χ² with 3 dof, p-value), and the per-point
// z = (F_paper − mean)/stderr of the published curve at our points with Δn >= both δ.
#pragma once
#include <Eigen/Core>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analysis/fit_table.hpp"
#include "analysis/kt_unit.hpp"
#include "config/yaml_node.hpp"

namespace softpack::verdict {

struct Tolerance {
  bool factor = false;  ///< within a factor `value` (else relative: |ours/paper − 1| <= value)
  double value = 0.0;
  bool met(double ours, double paper) const;
  std::string text() const;  ///< "factor 2", "±25 %"
};

struct Criteria {
  std::map<std::string, std::map<std::string, Tolerance>> tolerances;  ///< table1/table2 -> a, b, delta
  std::vector<std::string> readings;  ///< table2_unit.readings: m, mm, rad, deg
  double established_sigmas = 3.0;
  std::string select_scene = "soft-solid", test_scene = "soft-soft";
  double test_factor = 2.0;
  double joint_p_min = 0.01;
};
/// Reads `tolerances` and `table2_unit` of a criteria file; InputError at the key.
Criteria parse_criteria(const ConfigNode& criteria);

/// One scene's inputs: our fits (estimates), the jackknife covariance of Eq. 7's (a, b, c)
/// (NaN: none), the averages, and the published laws.
struct SceneInput {
  std::string scene;
  std::map<std::string, table::Estimate> normal;                     ///< a, b, c, delta
  std::optional<std::map<std::string, table::Estimate>> tangential;  ///< a, b, c [N/m of ht]
  Eigen::Matrix3d jackknife = Eigen::Matrix3d::Constant(kNaN);
  std::vector<double> delta_n, Fn, Fn_stderr, kt_delta_n, kt, kt_stderr;
  table::PublishedLaw paper_normal, paper_tangential;
};

struct Line {
  std::string table, scene, key;  ///< "table1", "soft-solid", "a"
  double ours = kNaN, error = kNaN, paper = kNaN;
  double deviation = kNaN;  ///< ours/paper − 1
  std::string tolerance;
  std::string status;  ///< "reproduced", "not reproduced", "unit undetermined", "no fit"
};

struct Curve {  ///< the published curve against our averages
  std::string scene;
  std::size_t points = 0;            ///< Δn >= max(δ ours, δ paper)
  std::size_t within_two = 0;        ///< |z| <= 2
  double median_abs_z = kNaN;
  double ratio_min = kNaN, ratio_max = kNaN;  ///< ours / paper's curve over those points
  double joint_chi2 = kNaN, joint_p = kNaN;   ///< (a, b, c) under the jackknife covariance
  bool jointly_consistent = false;            ///< joint_p >= the criteria's joint_p_min
  /// The paper's "F = 0 below δ": the largest mean force below our δ that is neither zero within
  /// two standard errors nor below 1e-6 of the largest force, over the largest force (0: none).
  double force_below_delta = 0.0;
};

struct Unit {
  std::vector<std::string> readings;
  std::map<std::string, std::vector<double>> q;  ///< scene -> geometric-mean q per reading (NaN: none established)
  std::map<std::string, std::vector<std::size_t>> established;  ///< scene -> points counted per reading
  std::string selected;                          ///< the reading selected on select_scene ("" : none)
  double test_q = kNaN;                          ///< test_scene's q in it
  bool passed = false;
};

struct Verdict {
  std::vector<Line> lines;
  std::vector<Curve> curves;
  Unit unit;
  std::size_t reproduced = 0, judged = 0;
};

/// metres of ht per unit of each reading name (m, mm, rad, deg) for a shell of radius Rs.
double metres_per_unit(const std::string& reading, double Rs);

Verdict judge(const std::vector<SceneInput>& scenes, const Criteria& criteria, double Rs);

/// The χ² survival function Q(x; dof) = P(χ²_dof > x), for integer dof >= 1 (closed forms).
double chi2_survival(double x, int dof);

/// P(|T| > t) for Student's t with integer ν >= 1 degrees of freedom (Abramowitz & Stegun 26.7.3-4).
double student_t_two_sided_p(double t, int nu);

/// The paper's prestrain claim ("this prestrain averages out the more simulations we average
/// over") as a test that can fail: at each point (rows: points, columns: seeds) the seeds' mean is
/// zero within its standard error, by Student's t with seeds − 1 degrees of freedom, and the
/// smallest p over the points, times the number of points (Bonferroni: valid whatever the
/// correlation between points of one seed), is the test's p. Independent zero-mean values pass;
/// a common offset (every seed shifted alike) fails once it exceeds a few standard errors.
struct ZeroMeanTest {
  double p = kNaN;          ///< min over points of the two-sided p, times the points (at most 1)
  double largest_t = kNaN;  ///< the largest |mean / standard error|
  std::size_t points = 0;
};
ZeroMeanTest zero_mean_test(const std::vector<std::vector<double>>& per_point_per_seed);

}  // namespace softpack::verdict
