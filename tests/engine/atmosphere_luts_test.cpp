// The atmosphere's precomputed tables (engine/atmosphere/atmosphere_luts.h) against the model's
// double-precision integrals (planet/atmosphere/atmosphere_reference.h) at texel centres, where the
// tables hold their own values (no interpolation): transmittance at the zenith and the horizon at
// three altitudes, single scattering at a handful of (r, mu, mu_s, nu). And the cache file: a second
// set of tables for the same parameters is read back bit for bit.
#include "engine/atmosphere/atmosphere_luts.h"
#include "planet/atmosphere/atmosphere_reference.h"
#include "tests/support/gpu_test.h"
#include "tests/support/temp_dir.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace globe::testing {
namespace {

constexpr double kRadius_m = 6360000.0;  // the reference implementation's Earth

double relativeError(double gpu, double cpu) { return std::abs(gpu - cpu) / std::max(std::abs(cpu), 1e-30); }

// (r, mu) of transmittance texel (x, y), as atmosphere_model.glsl maps it.
glm::dvec2 transmittanceTexel(const AtmosphereReference& ref, int x, int y) {
  const double b = ref.bottom_m(), t = ref.top_m(), H = std::sqrt(t * t - b * b);
  auto fromTexel = [](double u, double n) { return (u - 0.5 / n) / (1.0 - 1.0 / n); };
  const double rho = H * fromTexel((y + 0.5) / GLOBE_TRANSMITTANCE_H, GLOBE_TRANSMITTANCE_H);
  const double r = std::sqrt(rho * rho + b * b);
  const double dMin = t - r, dMax = rho + H;
  const double d = dMin + fromTexel((x + 0.5) / GLOBE_TRANSMITTANCE_W, GLOBE_TRANSMITTANCE_W) * (dMax - dMin);
  const double mu = d == 0.0 ? 1.0 : (H * H - rho * rho - d * d) / (2.0 * r * d);
  return {r, std::clamp(mu, -1.0, 1.0)};
}

class AtmosphereLutsTest : public GpuTest {};

TEST_F(AtmosphereLutsTest, TransmittanceMatchesDoubleIntegralAtZenithAndHorizon) {
  const AtmosphereParameters earth;
  const AtmosphereLuts luts(device(), earth, kRadius_m, "", 1);
  std::printf("tables (single scattering) computed in %.0f ms\n", luts.build_ms());
  const AtmosphereReference ref(earth, kRadius_m);
  for (int y : {0, 20, 50}) {
    for (int x : {0, GLOBE_TRANSMITTANCE_W / 2, GLOBE_TRANSMITTANCE_W - 1}) {  // zenith, between, horizon
      const glm::dvec2 rMu = transmittanceTexel(ref, x, y);
      const glm::dvec3 cpu = ref.transmittanceToTop(rMu.x, rMu.y);
      const float* gpu = luts.transmittanceData() + 4 * (y * GLOBE_TRANSMITTANCE_W + x);
      for (int c = 0; c < 3; ++c) {
        // 1 % relative, or 1e-5 absolute where the horizon's blue is almost gone.
        EXPECT_TRUE(relativeError(gpu[c], cpu[c]) < 0.01 || std::abs(gpu[c] - cpu[c]) < 1e-5)
            << "texel (" << x << ", " << y << ") r " << rMu.x << " mu " << rMu.y << " channel " << c << ": GPU "
            << gpu[c] << " CPU " << cpu[c];
      }
    }
  }
}

// (r, mu, mu_s, nu) of scattering texel (nu, mu_s, mu, r) as atmosphere_precompute.comp maps it.
glm::dvec4 scatteringTexel(const AtmosphereReference& ref, double muSMin, int iNu, int iMuS, int iMu, int iR) {
  const double b = ref.bottom_m(), t = ref.top_m(), H = std::sqrt(t * t - b * b);
  auto fromTexel = [](double u, double n) { return (u - 0.5 / n) / (1.0 - 1.0 / n); };
  const double rho = H * fromTexel((iR + 0.5) / GLOBE_SCATTERING_R, GLOBE_SCATTERING_R);
  const double r = std::sqrt(rho * rho + b * b);
  const double uMu = (iMu + 0.5) / GLOBE_SCATTERING_MU, half = GLOBE_SCATTERING_MU / 2;
  double mu;
  if (iMu < GLOBE_SCATTERING_MU / 2) {
    const double d = (r - b) + (rho - (r - b)) * fromTexel(1.0 - 2.0 * uMu, half);
    mu = d == 0.0 ? -1.0 : -(rho * rho + d * d) / (2.0 * r * d);
  } else {
    const double dMin = t - r, dMax = rho + H;
    const double d = dMin + (dMax - dMin) * fromTexel(2.0 * uMu - 1.0, half);
    mu = d == 0.0 ? 1.0 : (H * H - rho * rho - d * d) / (2.0 * r * d);
  }
  mu = std::clamp(mu, -1.0, 1.0);
  const double x = fromTexel((iMuS + 0.5) / GLOBE_SCATTERING_MU_S, GLOBE_SCATTERING_MU_S);
  const double dMin = t - b, dMax = H;
  const double D = -b * muSMin + std::sqrt(b * b * (muSMin * muSMin - 1.0) + t * t);
  const double A = (D - dMin) / (dMax - dMin);
  const double a = (A - x * A) / (1.0 + x * A);
  const double d = dMin + std::min(a, A) * (dMax - dMin);
  const double muS = std::clamp((H * H - d * d) / (2.0 * b * d), -1.0, 1.0);
  const double spread = std::sqrt(std::max((1.0 - mu * mu) * (1.0 - muS * muS), 0.0));
  const double nu = std::clamp(-1.0 + 2.0 * iNu / (GLOBE_SCATTERING_NU - 1.0), mu * muS - spread, mu * muS + spread);
  return {r, mu, muS, nu};
}

TEST_F(AtmosphereLutsTest, SingleScatteringMatchesDoubleIntegral) {
  const AtmosphereParameters earth;
  const AtmosphereLuts luts(device(), earth, kRadius_m, "", 1);
  const AtmosphereReference ref(earth, kRadius_m);
  // (nu, mu_s, mu, r): looking up and down, sun high and low, ground level and 5-20 km up.
  const int texels[][4] = {{7, 14, 50, 0}, {4, 10, 40, 4}, {2, 12, 55, 8}, {6, 13, 15, 3}, {5, 9, 48, 12}};
  for (const auto& t : texels) {
    const glm::dvec4 p = scatteringTexel(ref, luts.packed().radii.z, t[0], t[1], t[2], t[3]);
    glm::dvec3 rayleigh, mie;
    ref.singleScattering(p.x, p.y, p.z, p.w, rayleigh, mie);
    const int index = ((t[3] * GLOBE_SCATTERING_MU + t[2]) * GLOBE_SCATTERING_MU_S + t[1]) * GLOBE_SCATTERING_NU + t[0];
    const float* gpu = luts.scatteringData() + 4 * index;
    const double expected[4] = {rayleigh.x, rayleigh.y, rayleigh.z, mie.x};
    for (int c = 0; c < 4; ++c) {
      EXPECT_LT(relativeError(gpu[c], expected[c]), 0.01)
          << "r " << p.x << " mu " << p.y << " mu_s " << p.z << " nu " << p.w << " channel " << c << ": GPU " << gpu[c]
          << " CPU " << expected[c];
    }
  }
}

TEST_F(AtmosphereLutsTest, CacheFileGivesTheSameTables) {
  TempDir dir("atmosphere_cache");
  const AtmosphereParameters earth;
  const AtmosphereLuts computed(device(), earth, kRadius_m, dir.str());
  std::printf("tables (4 orders) computed in %.0f ms:", computed.build_ms());
  for (const AtmosphereLuts::Step& step : computed.stepTimes())
    std::printf(" %s %.0f ms,", step.name.c_str(), step.wall_ms);
  std::printf("\n");
  ASSERT_FALSE(computed.fromCache());
  const AtmosphereLuts read(device(), earth, kRadius_m, dir.str());
  ASSERT_TRUE(read.fromCache()) << read.cacheFile();
  std::printf("tables read from the cache in %.0f ms\n", read.build_ms());
  EXPECT_EQ(0, std::memcmp(computed.scatteringData(), read.scatteringData(), size_t(GLOBE_SCATTERING_TEXELS) * 16));
  EXPECT_EQ(0, std::memcmp(computed.transmittanceData(), read.transmittanceData(),
                           size_t(GLOBE_TRANSMITTANCE_W) * GLOBE_TRANSMITTANCE_H * 16));
  // Other parameters, another file.
  AtmosphereParameters thicker = earth;
  thicker.thickness_m = 80000.0;
  const AtmosphereLuts other(device(), thicker, kRadius_m, dir.str(), 1);
  EXPECT_FALSE(other.fromCache());
  EXPECT_NE(other.cacheFile(), computed.cacheFile());
}

}  // namespace
}  // namespace globe::testing
