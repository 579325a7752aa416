// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The size distribution of a population sample: bins, number densities and the
// derived sizes on synthetic populations with known answers; the correlated-sample interval.
#include "TestHelpers.hpp"

using namespace coagtest;

namespace {
const double pi = 3.14159265358979323846;
}

TEST(SizeBins, IntegerBinsHoldTheirSize)
{
    const SizeBins b = SizeBins::integer(30);
    ASSERT_EQ(b.size(), 30u);
    for (std::size_t k = 1; k <= 30; ++k) {
        EXPECT_EQ(b.index(double(k)), k - 1);
        EXPECT_EQ(b.centre(k - 1), double(k));
    }
    EXPECT_EQ(b.index(0.4), b.underflow());
    EXPECT_EQ(b.index(31.0), b.overflow());
    EXPECT_EQ(b.index(30.49), 29u);
}

TEST(SizeBins, LogBinsAreGeometric)
{
    const SizeBins b = SizeBins::logarithmic(1.0, 1000.0, 3);
    ASSERT_EQ(b.size(), 3u);
    EXPECT_NEAR(b.edges()[1], 10.0, 1e-12);
    EXPECT_NEAR(b.edges()[2], 100.0, 1e-10);
    EXPECT_EQ(b.index(1.0), 0u);
    EXPECT_EQ(b.index(9.99), 0u);
    EXPECT_EQ(b.index(b.edges()[1]), 1u);     // an edge belongs to the bin above it
    EXPECT_EQ(b.index(999.0), 2u);
    EXPECT_EQ(b.index(1000.0), b.overflow());
    EXPECT_EQ(b.index(0.5), b.underflow());
    EXPECT_NEAR(b.centre(1), std::sqrt(1000.0), 1e-10);
    EXPECT_THROW(SizeBins::logarithmic(0.0, 1.0, 3), std::invalid_argument);
    EXPECT_THROW(SizeBins::logarithmic(2.0, 1.0, 3), std::invalid_argument);
    EXPECT_THROW(SizeBins::logarithmic(1.0, 2.0, 0), std::invalid_argument);
    EXPECT_THROW(SizeBins::integer(0), std::invalid_argument);
}

// Three sizes 1, 2, 8 with weights 1, 2, 1 in a volume of 2: every answer by hand
TEST(SizeSample, SyntheticPopulationKnownAnswers)
{
    const std::vector<double> m{8.0, 1.0, 2.0}, w{1.0, 1.0, 2.0};
    const SizeBins b = SizeBins::integer(5);
    const double rho = 1000.0, unit = 1e-18;
    const SizeSample s = sizeSample(m, w, 2.0, b, rho, unit);
    EXPECT_DOUBLE_EQ(s.numberDensity[0], 0.5);
    EXPECT_DOUBLE_EQ(s.numberDensity[1], 1.0);
    EXPECT_DOUBLE_EQ(s.numberDensity[2], 0.0);
    EXPECT_DOUBLE_EQ(s.overflow, 0.5);
    EXPECT_DOUBLE_EQ(s.underflow, 0.0);
    const DerivedSizes& d = s.derived;
    EXPECT_DOUBLE_EQ(d.M0, 2.0);
    EXPECT_DOUBLE_EQ(d.meanMass, (8.0 + 1.0 + 4.0) / 4.0);
    // ln m: 0 (w 1), ln 2 (w 2), 3 ln 2 (w 1): mean ln 2 * 5/4; variance (ln 2)^2 * (25 + 1 + 1 + 49)/64 = 19/16
    const double l2 = std::log(2.0);
    EXPECT_NEAR(d.geometricMean, std::exp(1.25 * l2), 1e-14);
    EXPECT_NEAR(d.gsd, std::exp(l2 * std::sqrt(19.0 / 16.0)), 1e-14);
    EXPECT_DOUBLE_EQ(d.median, 2.0);
    // diameters: d(m) = (6 m unit/(pi rho))^(1/3) = a m^(1/3)
    const double a = std::cbrt(6.0 * unit / (pi * rho));
    const double dd[3] = {a, a * std::cbrt(2.0), 2.0 * a};   // m = 1, 2, 8
    const double ww[3] = {1.0, 2.0, 1.0};
    double s1 = 0, s2 = 0, s3 = 0, s4 = 0;
    for (int i = 0; i < 3; ++i) {
        s1 += ww[i] * dd[i];
        s2 += ww[i] * dd[i] * dd[i];
        s3 += ww[i] * std::pow(dd[i], 3);
        s4 += ww[i] * std::pow(dd[i], 4);
    }
    EXPECT_NEAR(d.d10, s1 / 4.0, 1e-12 * a);
    EXPECT_NEAR(d.d32, s3 / s2, 1e-12 * a);
    EXPECT_NEAR(d.d43, s4 / s3, 1e-12 * a);
    // by hand: d32 = a (1 + 2*2 + 8)/(1 + 2*2^(2/3) + 4)
    EXPECT_NEAR(d.d32, a * 13.0 / (5.0 + 2.0 * std::cbrt(4.0)), 1e-12 * a);
}

// A monodisperse population: gsd 1, every diameter the same, median the size
TEST(SizeSample, MonodisperseAndEvenMedian)
{
    const std::vector<double> m(7, 27.0), w(7, 0.3);
    const SizeSample s = sizeSample(m, w, 1.0, SizeBins::logarithmic(1, 1e3, 9), 1.0, pi / 6.0);
    EXPECT_NEAR(s.derived.gsd, 1.0, 1e-14);
    EXPECT_NEAR(s.derived.d10, 3.0, 1e-12);
    EXPECT_NEAR(s.derived.d32, 3.0, 1e-12);
    EXPECT_NEAR(s.derived.d43, 3.0, 1e-12);
    EXPECT_DOUBLE_EQ(s.derived.median, 27.0);
    double sum = s.underflow + s.overflow;
    for (double v : s.numberDensity) sum += v;
    EXPECT_NEAR(sum, 2.1, 1e-14);
    // even split of the weight: the midpoint of the two middle masses
    const SizeSample e = sizeSample({4.0, 1.0}, {1.0, 1.0}, 1.0, SizeBins::integer(4));
    EXPECT_DOUBLE_EQ(e.derived.median, 2.5);
    EXPECT_TRUE(std::isnan(e.derived.d10));      // no density given
    const SizeSample z = sizeSample({}, {}, 1.0, SizeBins::integer(4), 1.0);
    EXPECT_EQ(z.derived.M0, 0.0);
    EXPECT_TRUE(std::isnan(z.derived.meanMass));
}

// A lognormal number distribution (sampled with equal weights): the geometric mean and
// standard deviation and the Hatch-Choate diameters d_pq of its spheres
TEST(SizeSample, LognormalHatchChoate)
{
    Rng rng(18);
    const double mg = 50.0, sg = 1.8;
    std::vector<double> m, w;
    for (int i = 0; i < 200000; ++i) {
        // Box-Muller from the core's uniform generator
        const double u1 = rng.uniform(), u2 = rng.uniform();
        const double g = std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2.0 * pi * u2);
        m.push_back(mg * std::exp(std::log(sg) * g));
        w.push_back(1.0);
    }
    const SizeSample s = sizeSample(m, w, 1.0, SizeBins::logarithmic(1, 1e4, 20), 1.0, pi / 6.0);
    EXPECT_NEAR(s.derived.geometricMean / mg, 1.0, 0.01);
    EXPECT_NEAR(s.derived.gsd / sg, 1.0, 0.01);
    EXPECT_NEAR(s.derived.median / mg, 1.0, 0.01);
    // d = m^(1/3): lognormal with ln sigma_d = ln sg / 3; d_pq = dg exp((p+q-1)/2 ln^2 sigma_d)
    const double dg = std::cbrt(mg), l2 = std::pow(std::log(sg) / 3.0, 2);
    EXPECT_NEAR(s.derived.d10 / (dg * std::exp(0.5 * l2)), 1.0, 0.01);
    EXPECT_NEAR(s.derived.d32 / (dg * std::exp(2.5 * l2)), 1.0, 0.01);
    EXPECT_NEAR(s.derived.d43 / (dg * std::exp(3.5 * l2)), 1.0, 0.01);
}

TEST(CorrelatedMean, StudentQuantile)
{
    EXPECT_NEAR(studentT975(1), 12.7062, 1e-4);
    EXPECT_NEAR(studentT975(2), 4.3027, 1e-4);
    EXPECT_NEAR(studentT975(3), 3.182446, 1e-5);
    EXPECT_NEAR(studentT975(2.5), 3.574655, 1e-5);
    EXPECT_NEAR(studentT975(5), 2.570582, 1e-5);
    EXPECT_NEAR(studentT975(30), 2.042272, 1e-5);
    EXPECT_NEAR(studentT975(1e9), 1.96, 1e-3);
}

// AR(1) series: tau_int = (1 + phi)/(2 (1 - phi)); the interval covers the true mean 0
// about 95 % of the time, the iid one far less
TEST(CorrelatedMean, AutoregressiveCoverage)
{
    Rng rng(7);
    const double phi = 0.8;
    const double tauTrue = (1 + phi) / (2 * (1 - phi));
    int covered = 0, coveredIid = 0;
    double tauSum = 0;
    const int R = 400;
    for (int r = 0; r < R; ++r) {
        std::vector<double> x(2000);
        double v = 0;
        for (double& xi : x) {
            const double u1 = rng.uniform(), u2 = rng.uniform();
            v = phi * v + std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2.0 * pi * u2);
            xi = v;
        }
        const CorrelatedMean c = correlatedMean(x);
        tauSum += c.tauInt;
        covered += std::abs(c.mean) <= c.ci95;
        coveredIid += std::abs(c.mean) <= 1.96 * c.sd / std::sqrt(double(c.count));
        EXPECT_NEAR(c.neff, (c.sd * c.sd) / std::pow(c.ci95 / studentT975(2000.0 / (2 * c.window + 1)), 2),
                    1e-6 * c.neff);
    }
    EXPECT_NEAR(tauSum / R / tauTrue, 1.0, 0.1);
    EXPECT_GE(covered, int(0.91 * R));
    EXPECT_LE(covered, int(0.99 * R));
    EXPECT_LT(coveredIid, int(0.75 * R));
    // independent samples: tau_int about 1/2
    std::vector<double> y(4000);
    for (double& yi : y) yi = rng.uniform();
    const CorrelatedMean c = correlatedMean(y);
    EXPECT_NEAR(c.tauInt, 0.5, 0.1);
    EXPECT_TRUE(std::isnan(correlatedMean({1.0, 2.0}).ci95));
    EXPECT_EQ(correlatedMean(std::vector<double>(10, 3.0)).ci95, 0.0);
}
