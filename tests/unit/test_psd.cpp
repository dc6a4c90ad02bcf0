// Unit tests of the PSD value type (core/psd.*).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "psd.h"

using fabric::ParticleSizeDistribution;

namespace {

ParticleSizeDistribution parse(const std::string& text) {
  return ParticleSizeDistribution::parse(text, "test");
}

// The error message of parsing `text`, or "" if it parses.
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Psd, ReadsPointsAndComments) {
  auto p = parse("# sieve analysis\n0.1 0 # finest\n\n0.2 50\n0.4 100\n");
  ASSERT_EQ(p.points().size(), 3u);
  EXPECT_DOUBLE_EQ(p.d_min(), 0.1);
  EXPECT_DOUBLE_EQ(p.d_max(), 0.4);
}

TEST(Psd, DValuesInterpolateInLogDiameter) {
  // Percent linear in log d from 1 to 100: d(p) = 100^(p/100).
  auto p = parse("1 0\n100 100\n");
  EXPECT_NEAR(p.d10(), std::pow(100.0, 0.1), 1e-12);
  EXPECT_NEAR(p.d60(), std::pow(100.0, 0.6), 1e-12);
  EXPECT_NEAR(p.uniformity_coefficient(), 10.0, 1e-12);
  EXPECT_NEAR(p.percent_passing(10.0), 50.0, 1e-12);
}

TEST(Psd, ShippedSoilsHaveTheirUniformityCoefficient) {
  for (double cu : {2.0, 2.5, 3.0, 3.5}) {
    char name[64];
    snprintf(name, sizeof name, "%s/cu%.1f.txt", PSD_DIR, cu);
    auto p = ParticleSizeDistribution::read(name);
    EXPECT_NEAR(p.uniformity_coefficient(), cu, 0.01) << name;
  }
}

TEST(Psd, EqualMassIntervalsOfALogUniformSoil) {
  auto p = parse("1 0\n100 100\n");
  auto iv = p.equal_mass_intervals(20);
  ASSERT_EQ(iv.size(), 20u);
  double mass = 0.0;
  for (int k = 0; k < 20; ++k) {
    mass += iv[k].mass_fraction;
    double u = std::pow(100.0, k / 20.0), v = std::pow(100.0, (k + 1) / 20.0);
    EXPECT_NEAR(iv[k].d_lower, u, 1e-9 * u);
    EXPECT_NEAR(iv[k].d_upper, v, 1e-9 * v);
    // mass-weighted mean where mass is uniform in log d
    EXPECT_NEAR(iv[k].d_mean, (v - u) / std::log(v / u), 1e-9 * v);
    if (k > 0) {
      EXPECT_GT(iv[k].d_mean, iv[k - 1].d_mean);
    }
  }
  EXPECT_NEAR(mass, 1.0, 1e-12);
}

TEST(Psd, GapGradedSoilIsValidAndNoIntervalLiesInTheGap) {
  // 40 % between 0.1 and 0.2, nothing between 0.2 and 1, 60 % up to 2.
  auto p = parse("0.1 0\n0.2 40\n1.0 40\n2.0 100\n");
  auto iv = p.equal_mass_intervals(20);
  for (const auto& i : iv) {
    EXPECT_FALSE(i.d_mean > 0.2 + 1e-12 && i.d_mean < 1.0 - 1e-12)
        << "interval mean " << i.d_mean << " lies in the gap";
    EXPECT_GE(i.d_mean, i.d_lower * (1 - 1e-12));
  }
  EXPECT_NEAR(p.diameter_at_percent(40.0), 0.2, 1e-12);  // smallest such d
  EXPECT_NEAR(p.percent_passing(0.5), 40.0, 1e-12);
}

TEST(Psd, ParticleListFillsTheSolidVolume) {
  auto p = parse("1e-3 0\n2e-3 100\n");
  auto iv = p.equal_mass_intervals(5);
  auto list = fabric::particle_list(iv, 1e-6, 0.4);
  ASSERT_EQ(list.count.size(), 5u);
  for (size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(list.count[k], std::llround(list.target_count[k]));
    EXPECT_NEAR(list.target_count[k] * fabric::sphere_volume(list.diameter[k]),
                0.2 * 0.6e-6, 1e-18);
  }
  // rounding changes the solid volume by less than half a particle per class
  EXPECT_NEAR(list.solid_volume(), 0.6e-6,
              5 * 0.5 * fabric::sphere_volume(2e-3));
}

TEST(Psd, BadInputNamesTheValueAndWhatIsAllowed) {
  EXPECT_NE(error_of("0.1 0\n").find("at least 2 points"), std::string::npos);
  EXPECT_NE(error_of("").find("at least 2 points"), std::string::npos);
  EXPECT_NE(error_of("0.2 0\n0.1 100\n").find("strictly increasing"),
            std::string::npos);
  EXPECT_NE(error_of("0.1 0\n0.1 100\n").find("strictly increasing"),
            std::string::npos);
  EXPECT_NE(error_of("0.1 0\n0.2 60\n0.3 50\n0.4 100\n").find("must not decrease"),
            std::string::npos);
  EXPECT_NE(error_of("0.1 0\n0.2 120\n").find("0..100"), std::string::npos);
  EXPECT_NE(error_of("0.1 -5\n0.2 100\n").find("0..100"), std::string::npos);
  EXPECT_NE(error_of("0.1 0\n0.2 90\n").find("end at 100"), std::string::npos);
  EXPECT_NE(error_of("0.1 10\n0.2 100\n").find("start at 0"), std::string::npos);
  EXPECT_NE(error_of("0 0\n0.2 100\n").find("must be positive"), std::string::npos);
  EXPECT_NE(error_of("-1 0\n0.2 100\n").find("-1"), std::string::npos);
  EXPECT_NE(error_of("0.1 zero\n0.2 100\n").find("line 1"), std::string::npos);
  EXPECT_NE(error_of("0.1\n0.2 100\n").find("line 1"), std::string::npos);
  EXPECT_NE(error_of("0.1 0 7\n0.2 100\n").find("extra"), std::string::npos);
  EXPECT_NE(error_of("nan 0\n0.2 100\n").find("positive"), std::string::npos);
  EXPECT_THROW(ParticleSizeDistribution::read("/nonexistent/psd.txt"),
               std::invalid_argument);
  EXPECT_THROW(parse("1 0\n2 100\n").equal_mass_intervals(0),
               std::invalid_argument);
  EXPECT_THROW(parse("1 0\n2 100\n").equal_mass_intervals(101),
               std::invalid_argument);
}

TEST(Psd, FuzzedInputNeverCrashes) {
  std::mt19937_64 rng(7);
  const std::string alphabet = "0123456789.-+eE #\n\t xna";
  int parsed = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::string text;
    int len = rng() % 60;
    for (int i = 0; i < len; ++i) text += alphabet[rng() % alphabet.size()];
    try {
      auto p = parse(text);
      ++parsed;
      for (int n : {1, 7, 20}) {
        for (const auto& iv : p.equal_mass_intervals(n))
          ASSERT_TRUE(std::isfinite(iv.d_mean) && iv.d_mean > 0) << text;
      }
    } catch (const std::invalid_argument&) {
    }
  }
  // Structured fuzz: random valid-looking curves with flat parts and jumps.
  for (int trial = 0; trial < 5000; ++trial) {
    int n = 2 + rng() % 8;
    std::string text;
    double d = 1e-4 * (1 + rng() % 10), p = 0;
    for (int i = 0; i < n; ++i) {
      if (i == n - 1) p = 100;
      else if (i > 0 && rng() % 3) p = std::min(100.0, p + (rng() % 50));
      char line[64];
      snprintf(line, sizeof line, "%.17g %.17g\n", d, p);
      text += line;
      d *= 1.01 + (rng() % 1000) / 100.0;
    }
    auto psd = parse(text);  // every structured curve parses (a throw fails)
    for (const auto& iv : psd.equal_mass_intervals(20)) {
      ASSERT_TRUE(std::isfinite(iv.d_mean)) << text;
      ASSERT_GE(iv.d_mean, psd.d_min() * (1 - 1e-12)) << text;
      ASSERT_LE(iv.d_mean, psd.d_max() * (1 + 1e-12)) << text;
    }
  }
  // Mutated valid files: one to three characters replaced, so that many
  // still parse (random strings almost never do) and reach the split.
  const std::string valid = "# d (m) percent finer\n1e-4 0\n2e-4 30\n4e-4 70\n8e-4 100\n";
  int mutated = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::string text = valid;
    for (int k = 1 + static_cast<int>(rng() % 3); k > 0; --k)
      text[rng() % text.size()] = alphabet[rng() % alphabet.size()];
    try {
      auto psd = parse(text);
      ++mutated;
      for (const auto& iv : psd.equal_mass_intervals(20)) {
        ASSERT_TRUE(std::isfinite(iv.d_mean)) << text;
        ASSERT_GE(iv.d_mean, psd.d_min() * (1 - 1e-12)) << text;
        ASSERT_LE(iv.d_mean, psd.d_max() * (1 + 1e-12)) << text;
      }
    } catch (const std::invalid_argument&) {
    }
  }
  std::printf("parsed: %d of 20000 random strings, %d of 20000 mutated files\n",
              parsed, mutated);
  EXPECT_GT(mutated, 2000);
}
