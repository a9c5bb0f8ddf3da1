#include "contact/viscous_damping.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

namespace softpack::damping {
namespace {

// Integration of X'' = -X^(3/2) - zeta X^(1/4) X' by classic RK4 in scaled time.
// The undamped contact lasts tau ~ 3.2; d_tau resolves it with 32 000 steps, which puts the
// error of e well below 1e-9 (checked against the undamped e = 1 and against halving d_tau).
constexpr double kScaledStep = 1.0e-4;
constexpr double kScaledTimeLimit = 100.0;  // a contact still closed by then has stuck: e = 0

double acceleration(double X, double V, double zeta) {
  const double Xp = X > 0.0 ? X : 0.0;
  return -Xp * std::sqrt(Xp) - zeta * std::sqrt(std::sqrt(Xp)) * V;
}

}  // namespace

double restitution_from_zeta(double zeta) {
  double X = 0.0, V = 1.0;
  const double h = kScaledStep;
  for (double tau = 0.0; tau < kScaledTimeLimit; tau += h) {
    const double k1x = V, k1v = acceleration(X, V, zeta);
    const double k2x = V + 0.5 * h * k1v, k2v = acceleration(X + 0.5 * h * k1x, k2x, zeta);
    const double k3x = V + 0.5 * h * k2v, k3v = acceleration(X + 0.5 * h * k2x, k3x, zeta);
    const double k4x = V + h * k3v, k4v = acceleration(X + h * k3x, k4x, zeta);
    const double Xn = X + h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double Vn = V + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (Xn <= 0.0 && tau > 0.0) {
      // Separation inside this step: interpolate the exit speed linearly in X.
      const double s = X / (X - Xn);
      return -(V + s * (Vn - V));
    }
    if (Vn >= 0.0 && V < 0.0) return 0.0;  // turned back inward before separating: stuck
    X = Xn;
    V = Vn;
  }
  return 0.0;
}

namespace {

// Scenes are built many times with the same e (tests, sweeps): zeta_from_restitution remembers the answers.
std::mutex cache_mutex;
std::map<double, double> cache;

}  // namespace

void forget_zeta_cache() {
  const std::lock_guard lock(cache_mutex);
  cache.clear();
}

double zeta_from_restitution(double e) {
  if (!(e > 0.0 && e <= 1.0)) throw std::invalid_argument("restitution must be in (0, 1]");
  if (e == 1.0) return 0.0;
  {
    const std::lock_guard lock(cache_mutex);
    if (auto it = cache.find(e); it != cache.end()) return it->second;
  }
  // e(zeta) decreases monotonically; bracket, then bisect.
  double lo = 0.0, hi = 1.0;
  while (restitution_from_zeta(hi) > e) hi *= 2.0;
  while (hi - lo > 1e-11 * hi) {
    const double mid = 0.5 * (lo + hi);
    (restitution_from_zeta(mid) > e ? lo : hi) = mid;
  }
  const double zeta = 0.5 * (lo + hi);
  const std::lock_guard lock(cache_mutex);
  cache.emplace(e, zeta);
  return zeta;
}

double gamma_factor(double zeta, double m, double k) { return zeta * std::sqrt(m * k); }

}  // namespace softpack::damping
