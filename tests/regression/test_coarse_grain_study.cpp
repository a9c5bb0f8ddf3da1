// The coarse-grain validation's committed results (issue 17; data/coarse-grain/, made by `make
// coarse-grain` and `make coarse-grain-multi-contact`; CI does not recompute them;
// docs/coarse-grain.md, paper/coarse-grain.md): what holds — the speed-up target, the lateral
// stress ratio, a single contact of a resolved soft-particle against the law file — and what does
// not: the axial stress of the soft-particle medium, an expected failure with its measured gap,
// and its cause, the multi-contact stiffening.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "formats/law_file.hpp"

namespace softpack {
namespace {

// The study's reference setting (experiments/studies/coarse-grain.yaml): its report and probe.
const std::string kDir = SOFTPACK_SOURCE_DIR "/data/coarse-grain";
const std::string kCoarseReport = kDir + "/report/reference";

// Rows of a text file of numbers (comments and blank lines skipped; blocks concatenated).
std::vector<std::vector<double>> rows(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": missing (make coarse-grain)");
  std::vector<std::vector<double>> out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    out.emplace_back();
    for (double v; s >> v;) out.back().push_back(v);
  }
  return out;
}

TEST(CoarseGrainStudy, TheSoftParticleMediumIsAtLeast20TimesFaster) {
  std::ifstream in(kCoarseReport + "/summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j["seeds"].size(), 3u);
  for (const auto& s : j["speedup"]["per_seed"]) EXPECT_GE(s.get<double>(), 20.0);
  EXPECT_EQ(j["beyond_range"].get<long>(), 0) << "no soft contact left the laws' measured range";
}

// curves.dat columns: 1 strain, 2 phase, 3-4 sigma resolved, 5-6 sigma soft, 7-8 K0 resolved,
// 9-10 K0 soft.
TEST(CoarseGrainStudy, K0AgreesWithinTheSeedsSpreadFromTenPercentStrain) {
  int compared = 0;
  for (const auto& r : rows(kCoarseReport + "/curves.dat")) {
    if (r[1] != 1 || r[0] < 0.1 - 1e-9) continue;
    EXPECT_LE(std::abs(r[8] - r[6]), 3.0 * std::hypot(r[7], r[9])) << "strain " << r[0];
    ++compared;
  }
  EXPECT_GE(compared, 20);
}

// Expected failure (paper/coarse-grain.md): the pairwise laws give about half the resolved
// axial stress. Measured: soft / resolved 0.41-0.55 at every strain from 0.05 on. This test
// holds the gap where it was measured; it fails when it closes or widens.
TEST(CoarseGrainStudy, ExpectedFailureTheSoftMediumCarriesAboutHalfTheAxialStress) {
  for (const auto& r : rows(kCoarseReport + "/curves.dat")) {
    if (r[1] == 2 || r[0] < 0.05 - 1e-9) continue;  // loading and unloading (the shear block apart)
    const double ratio = r[4] / r[2];
    EXPECT_GT(ratio, 0.3) << "strain " << r[0];
    EXPECT_LT(ratio, 0.65) << "strain " << r[0] << ": the gap has closed; update paper/coarse-grain.md";
  }
}

// The cause: one resolved soft-particle, one wall, gives the law file's Eq. 7 (the mean of three
// packings other than the laws' within 15 % from dn 0.2; one packing alone spreads by about
// 10 %: 2.78, 2.86, 3.29 N at dn 0.3 against the law's 2.72 N); two and six walls pressing at
// once need more than 1.8 and 5 times the force per wall (measured 2.1-2.4 and 7.0-7.4).
TEST(CoarseGrainStudy, ASoftParticlePressedFromSeveralSidesIsStifferThanItsPairwiseLaw) {
  const LawFile laws = read_law_file(SOFTPACK_SOURCE_DIR "/data/radius/report/laws.json");
  const LawFit& n = laws.scenes.at("soft-solid").normal;
  double mean_one_wall[8] = {};
  for (const char* seed : {"301000", "302000", "303000"}) {
    double F[7][8] = {};
    for (const auto& r : rows(kDir + "/reference/multi-contact/seed-" + std::string(seed) + ".dat"))
      F[static_cast<int>(r[0])][static_cast<int>(std::lround(r[1] / 0.05))] = r[2];
    for (int k = 4; k <= 7; ++k) {  // dn 0.2 to 0.35
      mean_one_wall[k] += F[1][k] / 3.0;
      EXPECT_GT(F[2][k], 1.8 * F[1][k]) << seed << " dn " << 0.05 * k;
      EXPECT_GT(F[6][k], 5.0 * F[1][k]) << seed << " dn " << 0.05 * k;
    }
  }
  for (int k = 4; k <= 7; ++k) {
    const double dn = 0.05 * k, law = n.a.value * std::pow(dn, n.b.value) + n.c.value;
    EXPECT_NEAR(mean_one_wall[k], law, 0.15 * law) << "dn " << dn;
  }
}

}  // namespace
}  // namespace softpack
