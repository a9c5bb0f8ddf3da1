#include "analysis/verdict.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/seed_statistics.hpp"
#include "core/error.hpp"

namespace softpack::verdict {

bool Tolerance::met(double ours, double paper) const {
  if (!std::isfinite(ours) || !std::isfinite(paper) || paper == 0.0) return false;
  const double r = ours / paper;
  return factor ? (r >= 1.0 / value && r <= value) : std::abs(r - 1.0) <= value;
}

std::string Tolerance::text() const {
  return factor ? fmt::format("factor {:g}", value) : fmt::format("±{:g} %", 100.0 * value);
}

Criteria parse_criteria(const ConfigNode& root) {
  Criteria c;
  const ConfigNode tol = root.at("tolerances");
  tol.allow_only({"table1", "table2", "joint_p_min"});
  for (const char* table : {"table1", "table2"}) {
    const ConfigNode t = tol.at(table);
    t.allow_only(std::string(table) == "table1" ? std::vector<std::string>{"a", "b", "delta"}
                                                : std::vector<std::string>{"a", "b"});
    for (const std::string& key : t.keys()) {
      const ConfigNode k = t.at(key);
      k.allow_only({"factor", "relative"});
      Tolerance x;
      x.factor = k.has("factor");
      if (x.factor == k.has("relative")) k.fail("give one of factor (> 1) or relative (> 0)");
      const ConfigNode v = k.at(x.factor ? "factor" : "relative");
      x.value = v.number();
      if (!(x.factor ? x.value > 1.0 : x.value > 0.0) || !std::isfinite(x.value))
        v.fail(fmt::format("{} is not allowed; allowed: {}", x.value, x.factor ? "a factor > 1" : "a fraction > 0"));
      c.tolerances[table][key] = x;
    }
  }
  c.joint_p_min = tol.at("joint_p_min").number();
  if (!(c.joint_p_min > 0.0 && c.joint_p_min < 1.0)) tol.at("joint_p_min").fail("allowed: 0 < joint_p_min < 1");
  const ConfigNode u = root.at("table2_unit");
  u.allow_only({"readings", "established_sigmas", "select_scene", "test_scene", "test_factor"});
  for (const ConfigNode& r : u.at("readings").items()) c.readings.push_back(r.choice({"m", "mm", "rad", "deg"}));
  c.established_sigmas = u.at("established_sigmas").number();
  if (!(c.established_sigmas >= 0.0)) u.at("established_sigmas").fail("allowed: >= 0");
  c.select_scene = u.at("select_scene").choice({"soft-solid", "soft-soft"});
  c.test_scene = u.at("test_scene").choice({"soft-solid", "soft-soft"});
  if (c.select_scene == c.test_scene) u.at("test_scene").fail("the test scene must not be the select scene");
  c.test_factor = u.at("test_factor").number();
  if (!(c.test_factor > 1.0)) u.at("test_factor").fail("allowed: a factor > 1");
  return c;
}

double metres_per_unit(const std::string& reading, double Rs) { return table::kt_readings(Rs, {reading}).front().metres; }

double chi2_survival(double x, int dof) {
  if (!(x >= 0.0) || dof < 1) return kNaN;
  const double h = x / 2.0;
  double sum = 0.0, term = 0.0;
  if (dof % 2 == 0) {  // e^{-h} Σ_{i < dof/2} h^i / i!
    term = std::exp(-h);
    for (int i = 0; i < dof / 2; ++i) sum += term, term *= h / (i + 1);
    return std::min(1.0, sum);
  }
  // erfc(√h) + e^{-h} Σ_{i = 1}^{(dof-1)/2} h^{i-1/2} / Γ(i + 1/2)
  sum = std::erfc(std::sqrt(h));
  term = std::exp(-h) * std::sqrt(h) / std::tgamma(1.5);
  for (int i = 1; i <= (dof - 1) / 2; ++i) sum += term, term *= h / (i + 0.5);
  return std::min(1.0, sum);
}

double student_t_two_sided_p(double t, int nu) {
  if (nu < 1 || !std::isfinite(t)) return std::isfinite(t) ? kNaN : 0.0;
  const double theta = std::atan(std::abs(t) / std::sqrt(static_cast<double>(nu)));
  const double c = std::cos(theta), s = std::sin(theta);
  double A = 0.0;
  if (nu % 2 == 1) {  // (2/π)[θ + sinθ (cosθ + 2/3 cos³θ + … + (2·4…(ν−3))/(1·3…(ν−2)) cos^{ν−2}θ)]
    double sum = 0.0, term = c;
    for (int k = 1; k <= (nu - 1) / 2; ++k) sum += term, term *= c * c * (2.0 * k) / (2.0 * k + 1.0);
    A = 2.0 / std::numbers::pi * (theta + (nu > 1 ? s * sum : 0.0));
  } else {  // sinθ [1 + 1/2 cos²θ + (1·3)/(2·4) cos⁴θ + … + (1·3…(ν−3))/(2·4…(ν−2)) cos^{ν−2}θ]
    double sum = 0.0, term = 1.0;
    for (int k = 0; k < nu / 2; ++k) sum += term, term *= c * c * (2.0 * k + 1.0) / (2.0 * k + 2.0);
    A = s * sum;
  }
  return std::clamp(1.0 - A, 0.0, 1.0);
}

ZeroMeanTest zero_mean_test(const std::vector<std::vector<double>>& rows) {
  ZeroMeanTest t;
  double smallest = 1.0;
  t.largest_t = 0.0;
  for (const auto& row : rows) {
    if (row.size() < 2) throw InputError("a zero-mean test needs at least two seeds per point");
    const MeanError m = mean_error(row);
    const double se = m.error;
    if (!(se > 0.0)) throw InputError("a zero-mean test needs seeds that differ at every point");
    const double tt = m.mean / se;
    t.largest_t = std::max(t.largest_t, std::abs(tt));
    smallest = std::min(smallest, student_t_two_sided_p(tt, static_cast<int>(row.size()) - 1));
    ++t.points;
  }
  t.p = std::min(1.0, smallest * static_cast<double>(t.points));
  return t;
}

namespace {

// q per reading on one scene (analysis/kt_unit.hpp), the criteria's readings in their order.
void unit_q(const SceneInput& s, const Criteria& c, double Rs, std::vector<double>& q, std::vector<std::size_t>& n) {
  const table::KtUnitScene k = table::kt_unit_scene(s.scene, s.delta_n, s.Fn, s.Fn_stderr, s.kt_delta_n, s.kt, s.kt_stderr,
                                                    s.paper_normal, s.paper_tangential, table::kt_readings(Rs, c.readings),
                                                    c.established_sigmas);
  q.clear(), n.clear();
  std::size_t established = 0;
  for (const table::KtUnitPoint& p : k.points) established += p.established ? 1 : 0;
  for (double m : k.mean_log_q) q.push_back(std::isfinite(m) ? std::exp(m) : kNaN), n.push_back(established);
}

}  // namespace

Verdict judge(const std::vector<SceneInput>& scenes, const Criteria& c, double Rs) {
  Verdict v;
  // Table 2's unit first: it decides how a of Table 2 is judged.
  v.unit.readings = c.readings;
  for (const SceneInput& s : scenes) unit_q(s, c, Rs, v.unit.q[s.scene], v.unit.established[s.scene]);
  if (v.unit.q.count(c.select_scene) && v.unit.q.count(c.test_scene)) {
    const auto& qs = v.unit.q.at(c.select_scene);
    std::size_t best = qs.size();
    for (std::size_t r = 0; r < qs.size(); ++r)
      if (std::isfinite(qs[r]) && (best == qs.size() || std::abs(std::log(qs[r])) < std::abs(std::log(qs[best])))) best = r;
    if (best < qs.size()) {
      v.unit.selected = c.readings[best];
      v.unit.test_q = v.unit.q.at(c.test_scene)[best];
      v.unit.passed = std::isfinite(v.unit.test_q) && std::abs(std::log(v.unit.test_q)) <= std::log(c.test_factor);
    }
  }
  for (const SceneInput& s : scenes) {
    const auto line = [&](const char* table, const std::string& key, const table::Estimate* e, double paper, double scale) {
      Line l;
      l.table = table, l.scene = s.scene, l.key = key;
      l.paper = paper;
      const Tolerance& t = c.tolerances.at(table).at(key);
      l.tolerance = t.text();
      if (!e) {
        l.status = "no fit";
      } else {
        l.ours = e->value * scale, l.error = e->error * scale;
        l.deviation = l.ours / paper - 1.0;
        const bool undetermined = std::string(table) == "table2" && key == "a" && !v.unit.passed;
        l.status = undetermined ? "unit undetermined" : t.met(l.ours, paper) ? "reproduced" : "not reproduced";
        if (!undetermined) ++v.judged, v.reproduced += l.status == "reproduced" ? 1 : 0;
      }
      if (e == nullptr) ++v.judged;
      v.lines.push_back(l);
    };
    line("table1", "a", &s.normal.at("a"), s.paper_normal.a, 1.0);
    line("table1", "b", &s.normal.at("b"), s.paper_normal.b, 1.0);
    line("table1", "delta", &s.normal.at("delta"), s.paper_normal.delta, 1.0);
    const double unit = v.unit.passed ? metres_per_unit(v.unit.selected, Rs) : 1.0;
    line("table2", "a", s.tangential ? &s.tangential->at("a") : nullptr, s.paper_tangential.a, unit);
    line("table2", "b", s.tangential ? &s.tangential->at("b") : nullptr, s.paper_tangential.b, 1.0);

    Curve k;
    k.scene = s.scene;
    const double from = std::max(s.normal.at("delta").value, s.paper_normal.delta);
    std::vector<double> absz;
    for (std::size_t i = 0; i < s.delta_n.size(); ++i) {
      if (!(s.delta_n[i] >= from) || !(s.delta_n[i] > 0.0)) continue;
      const double p = s.paper_normal(s.delta_n[i]);
      if (!(p > 0.0) || !(s.Fn_stderr[i] > 0.0)) continue;
      const double z = (p - s.Fn[i]) / s.Fn_stderr[i];
      absz.push_back(std::abs(z));
      k.within_two += std::abs(z) <= 2.0 ? 1 : 0;
      const double r = s.Fn[i] / p;
      k.ratio_min = std::isfinite(k.ratio_min) ? std::min(k.ratio_min, r) : r;
      k.ratio_max = std::isfinite(k.ratio_max) ? std::max(k.ratio_max, r) : r;
    }
    k.points = absz.size();
    const double top = s.Fn.empty() ? 0.0 : *std::max_element(s.Fn.begin(), s.Fn.end());
    for (std::size_t i = 0; i < s.delta_n.size(); ++i)
      if (s.delta_n[i] < s.normal.at("delta").value &&
          !(std::abs(s.Fn[i]) <= 2.0 * s.Fn_stderr[i] || std::abs(s.Fn[i]) <= 1e-6 * top))
        k.force_below_delta = std::max(k.force_below_delta, std::abs(s.Fn[i]) / top);
    if (!absz.empty()) {
      std::sort(absz.begin(), absz.end());
      const std::size_t m = absz.size() / 2;
      k.median_abs_z = absz.size() % 2 ? absz[m] : 0.5 * (absz[m - 1] + absz[m]);
    }
    if (s.jackknife.allFinite()) {
      const Eigen::Vector3d d{s.normal.at("a").value - s.paper_normal.a, s.normal.at("b").value - s.paper_normal.b,
                              s.normal.at("c").value - s.paper_normal.c};
      const Eigen::LDLT<Eigen::Matrix3d> ldlt(s.jackknife);
      if (ldlt.info() == Eigen::Success && ldlt.isPositive()) {
        k.joint_chi2 = d.dot(ldlt.solve(d));
        k.joint_p = chi2_survival(k.joint_chi2, 3);
        k.jointly_consistent = k.joint_p >= c.joint_p_min;
      }
    }
    v.curves.push_back(k);
  }
  return v;
}

}  // namespace softpack::verdict
