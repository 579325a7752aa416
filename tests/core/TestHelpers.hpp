// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_TESTS_TESTHELPERS_HPP
#define COAGULATION_TESTS_TESTHELPERS_HPP

#include "coagulation/coagulation.hpp"
#include "coagulation/algorithms/EventLoop.hpp"
#include "coagulationReferences/smoluchowski/ExactSolutions.hpp"
#include "coagulationReferences/smoluchowski/NanbuMethod.hpp"
#include "coagulationReferences/smoluchowski/SmoluchowskiReference.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace coagtest {

using namespace coag;

//- Independent, well-mixed seeds for realisation r of a test.
inline std::uint64_t seedFor(std::uint64_t base, std::uint64_t r)
{
    return splitMix64Finalise(base * splitMix64Golden + r + 0x632BE59BD9B4E019ULL);
}

//- N unit-mass particles of the given weight in a cell of the given volume.
inline CellPopulation monodisperse(std::size_t N, double volume, double weight = 1.0)
{
    CellPopulation pop;
    pop.volume = volume;
    pop.particles.resize(N);
    for (std::size_t j = 0; j < N; ++j) {
        pop.particles[j].type.mass = 1.0;
        pop.particles[j].weight = weight;
        pop.particles[j].tag = static_cast<std::int64_t>(j);
    }
    return pop;
}

inline double totalMass(const CellPopulation& pop)
{
    double m = 0.0;
    for (const Particle& p : pop.particles) m += p.weight * p.type.mass;
    return m;
}

struct EnsembleResult {
    std::vector<std::array<RunningStatistics, 4>> moments;  // [time][k]
    std::vector<std::array<RunningStatistics, 4>> squaredError;  // (M_k - exact)^2 / exact^2
    StepStatistics steps;
};

//- R independent realisations, moments sampled at the given (increasing) times.
inline EnsembleResult runEnsemble(const std::string& algorithm, const CoagulationKernel& kernel,
                                  const InceptionModel& inception, const NumberControl& control,
                                  const std::function<CellPopulation()>& initial,
                                  const std::vector<double>& times, int R, std::uint64_t seed,
                                  const std::function<std::array<double, 4>(double)>& exact = {})
{
    EnsembleResult res;
    res.moments.resize(times.size());
    res.squaredError.resize(times.size());
    auto alg = makeCellAlgorithm(algorithm, kernel, inception, control);
    for (int r = 0; r < R; ++r) {
        Rng rng(seedFor(seed, static_cast<std::uint64_t>(r)));
        CellPopulation pop = initial();
        double t = 0.0;
        for (std::size_t i = 0; i < times.size(); ++i) {
            alg->advance(pop, times[i] - t, rng, res.steps);
            t = times[i];
            const std::array<double, 4> m = moments(pop);
            std::array<double, 4> ex{};
            if (exact) ex = exact(t);
            for (int k = 0; k < 4; ++k) {
                res.moments[i][k].add(m[k]);
                if (exact) {
                    const double e = (m[k] - ex[k]) / ex[k];
                    res.squaredError[i][k].add(e * e);
                }
            }
        }
    }
    return res;
}

//- Ensemble means of M_0..M_{nMoments-1} within `nSigma` standard errors of the exact values.
inline void expectMomentsMatch(const EnsembleResult& res, const std::vector<double>& times,
                               const std::function<std::array<double, 4>(double)>& exact,
                               int nMoments, const std::string& what, double nSigma = 4.0)
{
    for (std::size_t i = 0; i < times.size(); ++i) {
        const std::array<double, 4> ex = exact(times[i]);
        for (int k = 0; k < nMoments; ++k) {
            const RunningStatistics& s = res.moments[i][k];
            const double tol = nSigma * s.standardError() + 1e-9 * std::abs(ex[k]);
            EXPECT_NEAR(s.mean(), ex[k], tol)
                << what << ": M" << k << " at t = " << times[i] << " (mean " << s.mean()
                << ", exact " << ex[k] << ", SE " << s.standardError() << ", "
                << (s.standardError() > 0 ? (s.mean() - ex[k]) / s.standardError() : 0.0)
                << " SE off)";
        }
    }
}

} // namespace coagtest

#endif
