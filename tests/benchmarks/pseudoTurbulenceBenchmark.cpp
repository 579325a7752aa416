// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Throughput of the pseudo-turbulence model (PseudoTurbulence.hpp): velocity
// evaluations per second, single thread, for the paper's scale ratio L/eta = 1000 and a
// range of harmonic counts n0 x n: one point at a time (velocity), with the gradient
// (velocityGradient), and in batches of 1024 points (velocities); also the cost of drawing
// a field (construction). Each figure is the fastest of `repeats` blocks.
//
// Usage: pseudoTurbulenceBenchmark [evaluationsPerBlock (default 2e5)] [repeats (default 3)]
#include "coagulationReferences/pseudoTurbulence/PseudoTurbulence.hpp"
#include "coagulation/random/Rng.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace coag;

namespace {

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}

volatile double sink = 0;

} // namespace

int main(int argc, char** argv)
{
    const double perBlock = argc > 1 ? std::atof(argv[1]) : 2e5;
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
    const double twoPi = 6.283185307179586476925286766559;
    const std::size_t batch = 1024;

    std::printf("# L/eta = 1000, single thread; evaluations per second (fastest of %d blocks)\n",
                repeats);
    std::printf("%4s %4s %9s %14s %14s %14s %14s %12s\n", "n0", "n", "harmonics", "point/s",
                "point+grad/s", "batch/s", "harmonic-ev/s", "field us");
    const int configs[][2] = {{1, 16}, {1, 64}, {4, 16}, {8, 8}, {8, 32}, {16, 16}};
    for (const auto& c : configs) {
        const auto p = PseudoTurbulenceParameters::fromScales(1.0, twoPi / 1000, twoPi, c[0], c[1]);
        const PseudoTurbulence f(p, 1);
        const std::size_t H = f.harmonics();
        // evaluations per block: perBlock scaled to about the same work per configuration
        const std::size_t nEval =
            std::max<std::size_t>(batch, std::size_t(perBlock * 64.0 / double(H)) / batch * batch);
        Rng rng(3);
        std::vector<double> x(nEval), y(nEval), z(nEval), ux(batch), uy(batch), uz(batch);
        for (std::size_t i = 0; i < nEval; ++i) {
            x[i] = twoPi * rng.uniform();
            y[i] = twoPi * rng.uniform();
            z[i] = twoPi * rng.uniform();
        }
        double bestPoint = 0, bestGrad = 0, bestBatch = 0, bestField = 1e300;
        for (int r = 0; r < repeats; ++r) {
            auto t0 = std::chrono::steady_clock::now();
            double acc = 0;
            for (std::size_t i = 0; i < nEval; ++i) {
                const double xi[3] = {x[i], y[i], z[i]};
                double u[3];
                f.velocity(xi, u);
                acc += u[0];
            }
            auto t1 = std::chrono::steady_clock::now();
            bestPoint = std::max(bestPoint, double(nEval) / seconds(t0, t1));
            t0 = std::chrono::steady_clock::now();
            for (std::size_t i = 0; i < nEval / 4; ++i) {
                const double xi[3] = {x[i], y[i], z[i]};
                double u[3], g[3][3];
                f.velocityGradient(xi, u, g);
                acc += g[0][1];
            }
            t1 = std::chrono::steady_clock::now();
            bestGrad = std::max(bestGrad, double(nEval / 4) / seconds(t0, t1));
            t0 = std::chrono::steady_clock::now();
            for (std::size_t i = 0; i < nEval; i += batch) {
                f.velocities(batch, &x[i], &y[i], &z[i], ux.data(), uy.data(), uz.data());
                acc += ux[0];
            }
            t1 = std::chrono::steady_clock::now();
            bestBatch = std::max(bestBatch, double(nEval) / seconds(t0, t1));
            t0 = std::chrono::steady_clock::now();
            const int nFields = 200;
            for (int s = 0; s < nFields; ++s) {
                const PseudoTurbulence g(p, std::uint64_t(s) + 10);
                acc += g.wavenumber(0);
            }
            t1 = std::chrono::steady_clock::now();
            bestField = std::min(bestField, seconds(t0, t1) / nFields * 1e6);
            sink = sink + acc;
        }
        std::printf("%4d %4d %9zu %14.4g %14.4g %14.4g %14.4g %12.3g\n", c[0], c[1], H, bestPoint,
                    bestGrad, bestBatch, bestBatch * double(H), bestField);
    }
    return 0;
}
