// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The cost of growth: nanoseconds per particle of one growth pass (growPopulation over a
// step), for each kind of law, on one cell of N particles of a lognormal mass distribution
// (median 1, sigma_g of the diameter 1.5), single thread. The source step with growth makes
// two passes, G(dt/2) J(dt) G(dt/2), so a particle's growth costs twice the pass per split step.
// The jump process is unchanged by growth (the masses are fixed during J): no majorant headroom,
// no extra fictitious jumps.
//
// Usage: growthBenchmark [N (default 1e5)] [passes per block (default 200)] [blocks (default 5)]
#include "coagulation/coagulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace coag;

namespace {

struct Law {
    const char* name;
    const char* integration;
    GrowthLaw law;
};

std::vector<Law> laws()
{
    std::vector<Law> l(6);
    l[0] = {"constant", "closed", {}};
    l[0].law.addPower(1e-3, 0.0);
    l[1] = {"linear", "closed", {}};
    l[1].law.addPower(1e-2, 1.0);
    l[2] = {"surface", "closed", {}};
    l[2].law.addPower(5e-3, 2.0 / 3.0);
    l[3] = {"continuum", "closed", {}};
    l[3].law.addPower(5e-3, 1.0 / 3.0);
    l[4] = {"transition", "adaptive", {}};
    l[4].law.addTransition(5e-3, 1.0, 1.0, 1.0);
    l[5] = {"surface+oxidation", "adaptive", {}};
    l[5].law.addPower(5e-3, 2.0 / 3.0);
    l[5].law.addPower(-1e-3, 0.0);
    return l;
}

double argument(int argc, char** argv, int i, double fallback)
{
    if (argc <= i) return fallback;
    char* end = nullptr;
    const double v = std::strtod(argv[i], &end);
    if (end == argv[i] || *end != '\0' || !(v >= 1.0)) {
        std::fprintf(stderr, "Usage: growthBenchmark [N] [passes per block] [blocks] "
                             "(argument %d, '%s', is not a number >= 1)\n", i, argv[i]);
        std::exit(2);
    }
    return v;
}

} // namespace

int main(int argc, char** argv)
{
    const std::size_t N = static_cast<std::size_t>(argument(argc, argv, 1, 1e5));
    const int passes = static_cast<int>(argument(argc, argv, 2, 200));
    const int blocks = static_cast<int>(argument(argc, argv, 3, 5));
    const double dt = 0.01;

    // Masses lognormal: m = exp(3 ln(1.5) z), z standard normal (Box-Muller on the core's
    // uniforms; u1 in (0, 1])
    Rng rng(7);
    std::vector<double> masses(N);
    for (double& m : masses) {
        const double z = boxMuller(1.0 - rng.uniform(), rng.uniform()).first;
        m = std::exp(3.0 * std::log(1.5) * z);
    }

    std::printf("# growthBenchmark: one cell, %zu particles, %d passes of dt = %g per block, "
                "single thread\n", N, passes, dt);
    std::printf("# ns per particle and pass: best (median) of %d blocks; a split step makes 2 "
                "passes\n", blocks);
    std::printf("%-18s %-9s %10s %10s %12s\n", "law", "", "ns/pass", "(median)", "ns/step");
    for (Law& l : laws()) {
        std::vector<double> perPass;
        for (int b = 0; b < blocks; ++b) {
            CellPopulation pop;
            pop.volume = 1.0;
            pop.particles.resize(N);
            for (std::size_t j = 0; j < N; ++j) {
                pop.particles[j] = Particle{ParticleType{masses[j]}, 1.0, std::int64_t(j)};
            }
            StepStatistics stats;
            const auto t0 = std::chrono::steady_clock::now();
            for (int p = 0; p < passes; ++p) growPopulation(pop, l.law, dt, 0.0, stats);
            const auto t1 = std::chrono::steady_clock::now();
            perPass.push_back(std::chrono::duration<double>(t1 - t0).count() * 1e9
                              / (double(passes) * double(N)));
            if (pop.particles.size() != N) {
                std::fprintf(stderr, "growthBenchmark: %s lost particles\n", l.name);
                return 1;
            }
        }
        std::sort(perPass.begin(), perPass.end());
        std::printf("%-18s %-9s %10.1f %10.1f %12.1f\n", l.name, l.integration, perPass.front(),
                    perPass[perPass.size() / 2], 2.0 * perPass.front());
        std::fflush(stdout);
    }
    return 0;
}
