// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Fictitious jumps per real one of the Brownian kernels on a polydisperse population: one
// cell of N particles (default 4000) drawn from a lognormal of count median diameter dg and
// geometric standard deviation 1.5, 1800 kg/m3 in air at 1500 K and 1 bar, advanced over half
// a coagulation time 1/(K(dg, dg) n) in ten steps (the majorant group chosen as each starts),
// for each regime and dg. Prints a table; no assertion (doc/performance.md).
//
//   brownianFictitious [algorithm=SWA] [N=4000] [seed=1]
#include "coagulation/coagulation.hpp"
#include "coagulation/random/Normal.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace coag;

int main(int argc, char** argv)
{
    const std::string algorithm = argc > 1 ? argv[1] : "SWA";
    const std::size_t N = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 4000;
    const std::uint64_t seed = argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 1;
    const double sigmaG = 1.5, n0 = 1e14;  // [1/m3]
    GasState gas;
    gas.T = 1500.0;
    gas.p = 1e5;
    gas.mu = sutherlandViscosity(gas.T);
    const std::vector<double> dgs{3e-9, 30e-9, 60e-9, 80e-9, 100e-9, 120e-9, 200e-9, 300e-9, 1e-6};

    std::printf("# %s, %zu particles, lognormal sigma_g = %.2f, 1800 kg/m3, air at %.0f K and "
                "%.0f Pa (mean free path %.0f nm), half a coagulation time in 10 steps\n",
                algorithm.c_str(), N, sigmaG, gas.T, gas.p, 1e9 * gas.meanFreePath());
    std::printf("%-14s", "dg [nm]");
    for (double dg : dgs) std::printf(" %7.0f", dg * 1e9);
    std::printf("\n%-14s", "Kn = 2 l / dg");
    for (double dg : dgs) std::printf(" %7.2f", 2.0 * gas.meanFreePath() / dg);
    std::printf("\n");
    for (BrownianRegime regime :
         {BrownianRegime::freeMolecular, BrownianRegime::transition, BrownianRegime::continuum}) {
        std::printf("%-14s", brownianRegimeName(regime).c_str());
        for (double dg : dgs) {
            ParticleMaterial material{1800.0};
            material.massUnit = material.mass(dg);  // masses of order 1
            const BrownianKernel kernel(regime, gas, material);
            auto alg = makeCellAlgorithm(algorithm, kernel, InceptionModel{}, NumberControl{});
            Rng rng(seed);
            CellPopulation pop;
            pop.volume = static_cast<double>(N) / n0;
            for (std::size_t j = 0; j < N; ++j) {
                const double z = boxMuller(rng.uniform(), rng.uniform()).first;
                const double d = dg * std::exp(std::log(sigmaG) * z);
                pop.particles.push_back(
                    Particle{ParticleType{material.mass(d)}, 1.0, static_cast<std::int64_t>(j)});
            }
            const double tc = 1.0 / (kernel(ParticleType{1.0}, ParticleType{1.0}) * n0);
            StepStatistics stats;
            for (int step = 0; step < 10; ++step) alg->advance(pop, 0.05 * tc, rng, stats);
            std::printf(" %7.3f", static_cast<double>(stats.fictitious)
                                      / static_cast<double>(stats.coagulations));
        }
        std::printf("\n");
    }
    return 0;
}
