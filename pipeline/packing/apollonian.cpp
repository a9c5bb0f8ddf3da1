#include "packing/apollonian.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/error.hpp"
#include "core/types.hpp"

namespace softpack {
namespace {

using cplx = std::complex<double>;

/// |distance of centres - distance of tangency| / (scale), with signed radii 1/k so that one
/// formula covers external tangency and internal tangency with the bounding circle.
double tangency_residual(const DescartesCircle& p, const DescartesCircle& q) {
  const double touch = std::abs(1.0 / p.k + 1.0 / q.k);
  return std::abs(std::abs(p.w / p.k - q.w / q.k) - touch) / (std::abs(1.0 / p.k) + std::abs(1.0 / q.k));
}

/// One gap: three mutually tangent circles and the fourth circle already tangent to all of
/// them (the other Descartes solution). Indices into the unsorted working list.
struct Gap {
  std::int32_t a, b, c, opposite;
  int generation;
};

struct Node {
  DescartesCircle circle;
  int generation;
  std::array<std::int32_t, 3> parents;
};

}  // namespace

std::array<DescartesCircle, 2> descartes_solutions(const DescartesCircle& a, const DescartesCircle& b,
                                                   const DescartesCircle& c) {
  const double k_sum = a.k + b.k + c.k;
  // Clamped: a double root (as in the start) may round to a tiny negative discriminant.
  const double k_root = 2.0 * std::sqrt(std::max(0.0, a.k * b.k + b.k * c.k + c.k * a.k));
  const cplx w_sum = a.w + b.w + c.w;
  const cplx w_root = 2.0 * std::sqrt(a.w * b.w + b.w * c.w + c.w * a.w);
  auto residual = [&](const DescartesCircle& d) {
    return std::max({tangency_residual(d, a), tangency_residual(d, b), tangency_residual(d, c)});
  };
  // Either (+,+)/(-,-) or (+,-)/(-,+) are the two true circles; keep the better pairing.
  const std::array<DescartesCircle, 2> same{{{k_sum + k_root, w_sum + w_root}, {k_sum - k_root, w_sum - w_root}}};
  const std::array<DescartesCircle, 2> crossed{{{k_sum + k_root, w_sum - w_root}, {k_sum - k_root, w_sum + w_root}}};
  const double r_same = std::max(residual(same[0]), residual(same[1]));
  const double r_crossed = std::max(residual(crossed[0]), residual(crossed[1]));
  return r_same <= r_crossed ? same : crossed;
}

void validate(const ApollonianOptions& o) {
  if (!o.depth && !o.min_radius) throw InputError("give --depth and/or --min-radius (see --help)");
  if (o.min_radius && !(*o.min_radius >= kSmallestMinRadius && std::isfinite(*o.min_radius)))
    throw InputError(fmt::format("--min-radius: must be a number >= {:g} (the outer radius is 1; {:g} already gives "
                                 "1.4 million circles); got {:g}",
                                 kSmallestMinRadius, kSmallestMinRadius, *o.min_radius));
  if (o.depth && o.min_radius && *o.depth < 0)
    throw InputError(fmt::format("--depth: must be an integer >= 0; got {}", *o.depth));
  if (o.depth && !o.min_radius && (*o.depth < 0 || *o.depth > kMaxDepthWithoutMinRadius))
    throw InputError(fmt::format("--depth: must be an integer in [0, {}] without --min-radius (generation g alone has "
                                 "4*3^(g-1) circles); got {}",
                                 kMaxDepthWithoutMinRadius, *o.depth));
}

SizeExponentFit fit_size_exponent(const std::vector<ApollonianCircle>& circles, double r_lo, double r_hi) {
  SizeExponentFit fit{kNaN, r_lo, r_hi, 0};
  std::vector<double> radii;
  for (const auto& c : circles)
    if (c.generation >= 0) radii.push_back(c.r);
  std::sort(radii.begin(), radii.end());
  // 10 radii per decade from r_hi down, so that every decade weighs the same in the fit.
  std::vector<double> xs, ys;
  for (int j = 0;; ++j) {
    const double r = r_hi * std::pow(10.0, -0.1 * j);
    if (r < r_lo * (1 - 1e-12)) break;
    const auto above = radii.end() - std::upper_bound(radii.begin(), radii.end(), r);
    if (above == 0) continue;
    xs.push_back(std::log(r));
    ys.push_back(std::log(static_cast<double>(above)));
  }
  fit.points = static_cast<int>(xs.size());
  // Under a decade (depth 12 alone gives 0.5 decade, and 1.329): no exponent worth reporting.
  if (fit.points < 11) return fit;
  const double n = static_cast<double>(xs.size());
  const double mx = std::accumulate(xs.begin(), xs.end(), 0.0) / n;
  const double my = std::accumulate(ys.begin(), ys.end(), 0.0) / n;
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    sxy += (xs[i] - mx) * (ys[i] - my);
    sxx += (xs[i] - mx) * (xs[i] - mx);
  }
  fit.d_f = -sxy / sxx;
  return fit;
}

ApollonianPacking apollonian_gasket(const ApollonianOptions& options) {
  validate(options);
  const int depth = options.depth.value_or(std::numeric_limits<int>::max());
  const double min_radius = options.min_radius.value_or(0.0);

  std::vector<Node> nodes;
  nodes.push_back({{-1.0, {0.0, 0.0}}, -1, {-1, -1, -1}});
  nodes.push_back({{2.0, {-1.0, 0.0}}, 0, {-1, -1, -1}});
  nodes.push_back({{2.0, {1.0, 0.0}}, 0, {-1, -1, -1}});
  // The third inner circle: the upper of the two (here equal-curvature) Descartes solutions.
  const auto third = descartes_solutions(nodes[0].circle, nodes[1].circle, nodes[2].circle);
  nodes.push_back({third[0].w.imag() > 0 ? third[0] : third[1], 0, {-1, -1, -1}});

  ApollonianPacking out;
  out.per_generation.push_back(3);
  // The four gaps of the starting quadruple; each new circle splits its gap into three, and
  // each gap is keyed by its own occupant-to-be, so no gap is ever filled twice.
  std::vector<Gap> stack{{1, 2, 3, 0, 1}, {0, 2, 3, 1, 1}, {0, 1, 3, 2, 1}, {0, 1, 2, 3, 1}};
  while (!stack.empty()) {
    const Gap g = stack.back();
    stack.pop_back();
    const auto &a = nodes[g.a].circle, &b = nodes[g.b].circle, &c = nodes[g.c].circle, &d = nodes[g.opposite].circle;
    // Vieta: the two Descartes solutions sum to 2 (k1 + k2 + k3) (and likewise for w); the
    // opposite circle is one of them, the circle of this gap the other. Exact for integers.
    const DescartesCircle fill{2.0 * (a.k + b.k + c.k) - d.k, 2.0 * (a.w + b.w + c.w) - d.w};
    const double r = 1.0 / fill.k;
    if (g.generation > depth || r < min_radius) {
      out.complete_above = std::max(out.complete_above, r);
      continue;
    }
    const auto id = static_cast<std::int32_t>(nodes.size());
    nodes.push_back({fill, g.generation, {g.a, g.b, g.c}});
    if (out.per_generation.size() <= static_cast<std::size_t>(g.generation)) out.per_generation.resize(g.generation + 1);
    ++out.per_generation[g.generation];
    stack.push_back({g.b, g.c, id, g.a, g.generation + 1});
    stack.push_back({g.a, g.c, id, g.b, g.generation + 1});
    stack.push_back({g.a, g.b, id, g.c, g.generation + 1});
  }

  std::vector<ApollonianCircle> circles(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Node& n = nodes[i];
    // "+ 0.0" turns -0 into 0, so that mirror-image circles print and sort alike.
    circles[i] = {n.circle.w.real() / n.circle.k + 0.0, n.circle.w.imag() / n.circle.k + 0.0,
                  1.0 / std::abs(n.circle.k), n.circle.k, n.generation, n.parents};
  }
  // Sorted by radius descending, then x, then y; the bounding circle (radius 1) comes first.
  std::vector<std::int32_t> order(circles.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::int32_t p, std::int32_t q) {
    const auto &u = circles[p], &v = circles[q];
    if (u.r != v.r) return u.r > v.r;
    if (u.x != v.x) return u.x < v.x;
    return u.y < v.y;
  });
  std::vector<std::int32_t> rank(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) rank[order[i]] = static_cast<std::int32_t>(i);
  out.circles.reserve(circles.size());
  for (const std::int32_t i : order) {
    ApollonianCircle c = circles[i];
    for (auto& p : c.parents)
      if (p >= 0) p = rank[p];
    out.circles.push_back(c);
  }
  out.fit = fit_size_exponent(out.circles, out.complete_above, kFitLargestRadius);
  return out;
}

}  // namespace softpack
