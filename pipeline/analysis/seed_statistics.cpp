#include "analysis/seed_statistics.hpp"

#include <algorithm>
#include <cmath>

#include "core/types.hpp"

namespace softpack {

MeanError mean_error(const std::vector<double>& v, FewSeeds few) {
  const double n = static_cast<double>(v.size());
  const double unknown = few == FewSeeds::zero ? 0.0 : kNaN;
  if (v.empty()) return {unknown, unknown};
  MeanError m;
  for (double x : v) m.mean += x / n;
  if (v.size() < 2) return {m.mean, unknown};
  double ss = 0.0;
  for (double x : v) ss += (x - m.mean) * (x - m.mean);
  m.error = std::sqrt(ss / (n - 1.0) / n);
  return m;
}

Eigen::Matrix4d jackknife_covariance(const std::vector<Eigen::Vector4d>& leave_one_out) {
  const double n = static_cast<double>(leave_one_out.size());
  if (leave_one_out.size() < 2) return Eigen::Matrix4d::Constant(kNaN);
  Eigen::Vector4d mean = Eigen::Vector4d::Zero();
  for (const auto& t : leave_one_out) mean += t / n;
  Eigen::Matrix4d cov = Eigen::Matrix4d::Zero();
  for (const auto& t : leave_one_out) cov += (t - mean) * (t - mean).transpose();
  return cov * ((n - 1.0) / n);
}

double jackknife_error(const std::vector<double>& leave_one_out) {
  const double n = static_cast<double>(leave_one_out.size());
  if (leave_one_out.size() < 2) return kNaN;
  double mean = 0.0, ss = 0.0;
  for (double t : leave_one_out) mean += t / n;
  for (double t : leave_one_out) ss += (t - mean) * (t - mean);
  return std::sqrt(ss * ((n - 1.0) / n));
}

double rank_quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(std::lround(q * static_cast<double>(values.size() - 1)))];
}

}  // namespace softpack
