// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Throughput of the cell algorithms: events (accepted + fictitious coagulations) per second
// for N computational particles in one cell, single thread; and the accepted (real) events
// alone, the rate doc/performance.md reports (for SWA with the additive kernel, whose majorant is exact,
// the two differ only by the rejected j1 == j2 proposals, 1/N of them).
//
// The particle number is held roughly constant by timing short windows of physical time and
// re-filling the cell (untimed) between windows: SWA keeps N exactly (no inception here);
// DSA loses at most ~20 % of its particles per window. Each window is one advance() call, so
// the O(N) tree build per call is included in the timing.
//
// Each case is measured in `repeats` blocks of at least minEvents/repeats events; the table
// shows the fastest block (least disturbed by other load on the machine) and the median.
//
// Usage: coagulationBenchmark [minEventsPerCase (default 3e6)] [maxN (default 1e6)] [repeats (default 3)]
//                             [algorithm (SWA, DSA1 or all)] [kernel (additive, constant or all;
//                              or brownianFreeMolecular, brownianContinuum, brownianTransition)]
//                             [sizes: N,N,... (default 1e3,1e4,1e5,1e6), those up to maxN]
// COAGULATION_LOOKAHEAD=0 in the environment switches the event loop's draws made ahead off
// (DrawsAhead::never; the same events, so a same-binary comparison of their cost).
#include "coagulation/coagulation.hpp"
#include "coagulation/algorithms/EventLoop.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace coag;

namespace {

CellPopulation fill(std::size_t N)
{
    CellPopulation pop;
    pop.volume = static_cast<double>(N);  // density 1
    pop.particles.resize(N);
    for (std::size_t j = 0; j < N; ++j) pop.particles[j].tag = static_cast<std::int64_t>(j);
    return pop;
}

const std::vector<std::string> brownianKernels{"brownianFreeMolecular", "brownianContinuum",
                                               "brownianTransition"};

//- The kernel of the name: the core's kernels with K0 = 1, or the Brownian ones of 10 nm
//  monomers (1800 kg/m3, masses in monomers) in air at 1500 K and 1 bar; k11 = K(1, 1), so that
//  the windows, in units of 1/(K11 n), take about as many events as the constant kernel's
std::unique_ptr<CoagulationKernel> benchmarkKernel(const std::string& name, double& k11)
{
    k11 = 1.0;
    const auto b = std::find(brownianKernels.begin(), brownianKernels.end(), name);
    if (b == brownianKernels.end()) return makeKernel(name, 1.0);
    GasState gas;
    gas.T = 1500.0;
    gas.p = 1e5;
    gas.mu = sutherlandViscosity(gas.T);
    ParticleMaterial material{1800.0};
    material.massUnit = material.mass(10e-9);
    const BrownianRegime regime = b == brownianKernels.begin() ? BrownianRegime::freeMolecular
                                  : b == brownianKernels.begin() + 1 ? BrownianRegime::continuum
                                                                     : BrownianRegime::transition;
    auto kernel = std::make_unique<BrownianKernel>(regime, gas, material);
    k11 = (*kernel)(ParticleType{1.0}, ParticleType{1.0});
    return kernel;
}

struct Result {
    double events = 0;
    double accepted = 0;
    double seconds = 0;
    double bytesPerParticle = 0;
    double fictitiousFraction = 0;
};

Result runBlock(const std::string& algName, const std::string& kernelName, std::size_t N,
           double minEvents)
{
    double k11 = 1.0;
    auto kernel = benchmarkKernel(kernelName, k11);
    const char* lookahead = std::getenv("COAGULATION_LOOKAHEAD");
    auto alg = detail::makeCellAlgorithm(algName, *kernel, InceptionModel{}, NumberControl{},
                                         lookahead && std::string(lookahead) == "0"
                                             ? DrawsAhead::never
                                             : DrawsAhead::whereTheyPay);
    const bool dsa = algName != "SWA";
    // physical time per window (K0 = 1, density 1)
    const double window = (dsa ? (kernelName == "additive" ? 0.2 : 0.5)
                               : (kernelName == "additive" ? 0.5 : 1.0)) / k11;
    Rng rng(12345);
    StepStatistics stats;
    Result r;
    CellPopulation pop = fill(N);
    {
        // warm-up (allocations, page faults)
        CellPopulation w = fill(N);
        StepStatistics s;
        alg->advance(w, window * 0.05, rng, s);
    }
    while (r.events < minEvents) {
        pop = fill(N);
        const std::uint64_t before = stats.coagulations + stats.fictitious;
        const std::uint64_t acceptedBefore = stats.coagulations;
        const auto t0 = std::chrono::steady_clock::now();
        alg->advance(pop, window, rng, stats);
        const auto t1 = std::chrono::steady_clock::now();
        r.seconds += std::chrono::duration<double>(t1 - t0).count();
        r.events += static_cast<double>(stats.coagulations + stats.fictitious - before);
        r.accepted += static_cast<double>(stats.coagulations - acceptedBefore);
        const double bytes = static_cast<double>(pop.particles.capacity() * sizeof(Particle)
                                                 + alg->workspaceBytes());
        r.bytesPerParticle = bytes / static_cast<double>(N);
    }
    r.fictitiousFraction =
        static_cast<double>(stats.fictitious) / static_cast<double>(stats.coagulations + stats.fictitious);
    return r;
}

struct Summary {
    double events = 0;
    double bestRate = 0;
    double medianRate = 0;
    double bestAcceptedRate = 0;  // accepted events per second in the fastest block
    double bytesPerParticle = 0;
    double fictitiousFraction = 0;
};

Summary run(const std::string& algName, const std::string& kernelName, std::size_t N,
            double minEvents, int repeats)
{
    Summary s;
    std::vector<double> rates;
    double best = 0;
    for (int i = 0; i < repeats; ++i) {
        const Result r = runBlock(algName, kernelName, N, minEvents / repeats);
        rates.push_back(r.events / r.seconds);
        if (rates.back() > best) {
            best = rates.back();
            s.bestAcceptedRate = r.accepted / r.seconds;
        }
        s.events += r.events;
        s.bytesPerParticle = r.bytesPerParticle;
        s.fictitiousFraction = r.fictitiousFraction;
    }
    std::sort(rates.begin(), rates.end());
    s.bestRate = rates.back();
    s.medianRate = rates[rates.size() / 2];
    return s;
}

//- argv[i] as a positive number, or the default when absent; anything else ends the run
double positiveArgument(int argc, char** argv, int i, double fallback)
{
    if (argc <= i) return fallback;
    char* end = nullptr;
    const double v = std::strtod(argv[i], &end);
    if (end == argv[i] || *end != '\0' || !(v > 0.0)) {
        std::fprintf(stderr,
                     "Usage: coagulationBenchmark [minEventsPerCase (default 3e6)] [maxN (default "
                     "1e6)] [repeats (default 3)]\n(argument %d, '%s', is not a positive number)\n",
                     i, argv[i]);
        std::exit(2);
    }
    return v;
}

} // namespace

int main(int argc, char** argv)
{
    const double minEvents = positiveArgument(argc, argv, 1, 3e6);
    const double maxN = positiveArgument(argc, argv, 2, 1e6);
    const int repeats = static_cast<int>(positiveArgument(argc, argv, 3, 3));
    const std::string onlyAlg = argc > 4 ? argv[4] : "all";
    const std::string onlyKernel = argc > 5 ? argv[5] : "all";
    std::vector<double> sizes{1e3, 1e4, 1e5, 1e6};
    if (argc > 6) {
        sizes.clear();
        for (const char* p = argv[6]; *p != '\0';) {
            char* end = nullptr;
            const double N = std::strtod(p, &end);
            if (end == p || !(N >= 2.0 && N <= 1e9) || (*end != ',' && *end != '\0')) {
                std::fprintf(stderr, "coagulationBenchmark: sizes '%s' is not a list N,N,... "
                                     "of particle numbers from 2 to 1e9\n", argv[6]);
                return 1;
            }
            sizes.push_back(N);
            p = *end == ',' ? end + 1 : end;
        }
    }
    for (const auto& [given, allowed] :
         {std::pair<std::string, std::vector<std::string>>{onlyAlg, {"SWA", "DSA1", "all"}},
          {onlyKernel, {"additive", "constant", "all", brownianKernels[0], brownianKernels[1],
                        brownianKernels[2]}}}) {
        if (std::find(allowed.begin(), allowed.end(), given) == allowed.end()) {
            std::fprintf(stderr, "coagulationBenchmark: unknown algorithm or kernel '%s'\n",
                         given.c_str());
            return 1;
        }
    }
    std::printf("# coagulationBenchmark: one cell, K0 = 1, density 1, single thread\n");
    std::printf("# events = accepted + fictitious coagulation jumps; timing includes the tree build\n");
    std::printf("# best (and median) of %d blocks; bytes/ptcl = (particle vector + sum tree) / N\n",
                repeats);
    std::printf("# Macc/s, ns/acc: the accepted (real) events of the same fastest block\n");
    std::printf("%-5s %-9s %9s %11s %10s %10s %9s %8s %8s %10s %8s\n", "alg", "kernel", "N", "events",
                "Mevents/s", "(median)", "ns/event", "Macc/s", "ns/acc", "bytes/ptcl", "fict.");
    for (const std::string alg : {"SWA", "DSA1"}) {
        if (onlyAlg != "all" && alg != onlyAlg) continue;
        std::vector<std::string> kernels{"additive", "constant"};
        if (onlyKernel != "all") kernels = {onlyKernel};
        for (const std::string& kernel : kernels) {
            for (double N : sizes) {
                if (N > maxN) continue;
                const Summary r =
                    run(alg, kernel, static_cast<std::size_t>(N), minEvents, repeats);
                std::printf("%-5s %-9s %9.0f %11.0f %10.2f %10.2f %9.1f %8.2f %8.1f %10.1f %8.4f\n",
                            alg.c_str(), kernel.c_str(), N, r.events, r.bestRate / 1e6,
                            r.medianRate / 1e6, 1e9 / r.bestRate, r.bestAcceptedRate / 1e6,
                            1e9 / r.bestAcceptedRate, r.bytesPerParticle, r.fictitiousFraction);
                std::fflush(stdout);
            }
        }
    }
    return 0;
}
