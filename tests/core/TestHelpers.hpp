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

//- Air at T [K] and p [Pa], its viscosity by Sutherland's law
inline GasState air(double T, double p)
{
    GasState g;
    g.T = T;
    g.p = p;
    g.mu = sutherlandViscosity(T);
    return g;
}

//- Spheres of the density whose mass unit is one sphere of the diameter (masses in monomers)
inline ParticleMaterial monomersOf(double density, double diameter)
{
    ParticleMaterial m{density};
    m.massUnit = m.mass(diameter);
    return m;
}

//- The diameters of the majorant grids: 1 nm to 100 um, five a decade
inline std::vector<double> gridDiameters()
{
    std::vector<double> d;
    for (int i = 0; i <= 25; ++i) d.push_back(1e-9 * std::pow(10.0, i / 5.0));
    return d;
}

//- The closed cells of the long-time Brownian tests: free-molecular, 10 nm spheres of
//  1800 kg/m3 in air at 1500 K and 1 bar (the free-molecular kernel is homogeneous, so the size
//  does not matter), and continuum without slip, 1 um spheres of 1000 kg/m3 in air at 298 K
//  and 100 bar (Kn = 0.0013, Cunningham factor 1.002 at the start, closer to 1 as they grow).
//  Masses in the monomer's.
inline BrownianKernel selfPreservingKernel(BrownianRegime regime)
{
    if (regime == BrownianRegime::freeMolecular) {
        return BrownianKernel(regime, air(1500.0, 1e5), monomersOf(1800.0, 10e-9));
    }
    GasState gas;
    gas.T = 298.15;
    gas.p = 1e7;
    gas.mu = 1.8e-5;
    return BrownianKernel(regime, gas, monomersOf(1000.0, 1e-6));
}

//- M0..M3 of a discrete distribution, n[l] the number of (l + 1)-mers
inline std::array<double, 4> discreteMoments(const Eigen::VectorXd& n)
{
    std::array<double, 4> m{0, 0, 0, 0};
    for (Eigen::Index l = 0; l < n.size(); ++l) {
        double p = 1.0;
        for (int k = 0; k < 4; ++k) {
            m[k] += p * n[l];
            p *= static_cast<double>(l + 1);
        }
    }
    return m;
}

//- The discrete Smoluchowski reference from N0 monomers at the given times (ascending), a
//  function of t for expectMomentsMatch: M0..M3 with the sizes truncated at L = 800, checked
//  against L = 400 (the truncation must change M0..M2 by less than 1e-6, else the test fails)
inline std::function<std::array<double, 4>(double)>
discreteReference(const CoagulationKernel& kernel, double N0, const std::vector<double>& times,
                  const std::string& what)
{
    std::vector<std::array<double, 4>> reference[2];
    for (int level = 0; level < 2; ++level) {
        const std::size_t L = 400u << level;
        DiscreteSmoluchowski ode(kernel, L);
        ode.setTolerances(1e-10, 1e-14 * N0);  // the default absolute tolerance for N0 = 1
        Eigen::VectorXd n = Eigen::VectorXd::Zero(Eigen::Index(L));
        n[0] = N0;
        double t = 0.0;
        for (double ti : times) {
            n = ode.integrate(n, t, ti);
            t = ti;
            reference[level].push_back(discreteMoments(n));
        }
    }
    for (std::size_t i = 0; i < times.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(reference[0][i][k] / reference[1][i][k], 1.0, 1e-6)
                << what << ": the truncation changes M" << k << " at t = " << times[i];
        }
    }
    return [times, moments = reference[1]](double t) {
        std::size_t i = 0;
        while (i + 1 < times.size() && times[i] != t) ++i;
        return moments[i];
    };
}

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
