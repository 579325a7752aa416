// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// ductReference: the constant-kernel duct of Patterson & Wagner (section 3.1) with the core's
// cell algorithms and exact one-dimensional advection, without OpenFOAM.
//
// Why: it separates what a cell algorithm does at finite n (a method bias) from what the
// OpenFOAM layer does (tracking, cell sorting, particle creation), and it is fast enough for
// studies of many realisations. Same splittings as coagulationFoam, with S inception +
// coagulation in every cell and A every particle moving by u times the time (leaving at
// x >= L): Lie S(dt) A(dt) (the paper's) or Strang A(dt/2) S(dt) A(dt/2); samples after the
// step from tRelax on.
//
//   ductReference ALGORITHM n seed [endTime] [--cells] [--dt DT] [--splitting Lie|Strang]
//                 [--K0 K0] [--sample INTERVAL]
//
// prints, for the time-averaged M_{n,k}, the mean relative error to the analytic cell
// averages (eqs 39-45) over the last 20 cells; --cells prints every cell. Defaults: the
// paper's dt = 1e-4, Lie, K0 = 1e-5 (K0 = 1e-30: no coagulation, M1 exact as eq 41), samples
// every 5e-3.
#include "coagulation/coagulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace {

// Parameters of section 3.1 (the tutorial constantKernelDuct)
constexpr double L = 0.2, u = 1.0, inceptionRate = 3e8;
constexpr double tRelax = 0.4;
double dt = 1e-4, K0 = 1e-5, sampleInterval = 5e-3;
constexpr int nCells = 50;
constexpr double dx = L / nCells;

//- Integral of the analytic m_k (eqs 39, 41, 43, 45; I0 = inceptionRate/3) from 0 to x
double analyticIntegral(int k, double x)
{
    const double I0 = inceptionRate / 3.0;
    const double a = 1.5 * I0 / u;
    switch (k) {
    case 0: {
        const double b = std::sqrt(1.5 * I0 * K0) / u;
        return std::sqrt(6.0 * I0 / K0) / b * std::log(std::cosh(b * x));
    }
    case 1: return a * x * x;
    case 2: return a * x * x + 0.75 * I0 * I0 * K0 / std::pow(u, 3) * std::pow(x, 4);
    default:
        return a * x * x + 2.25 * I0 * I0 * K0 / std::pow(u, 3) * std::pow(x, 4)
               + 0.9 * std::pow(I0, 3) * K0 * K0 / std::pow(u, 5) * std::pow(x, 6);
    }
}

struct DuctParticle {
    double x, mass, weight;
};

int cellOf(double x)
{
    return std::min(nCells - 1, static_cast<int>(x / dx));
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 4) {
        std::fprintf(stderr, "usage: %s SWA|DSA1|DSA2 n seed [endTime] [--cells] [--dt DT] "
                             "[--splitting Lie|Strang] [--K0 K0] [--sample INTERVAL]\n", argv[0]);
        return 2;
    }
    try {
        const std::string algorithm = argv[1];
        const double n = std::atof(argv[2]);
        const unsigned long long seed = std::strtoull(argv[3], nullptr, 10);
        const double endTime = argc > 4 && argv[4][0] != '-' ? std::atof(argv[4]) : 4.0;
        bool perCell = false, strang = false;
        for (int a = 4; a < argc; ++a) {
            const std::string arg = argv[a];
            const bool value = a + 1 < argc;
            if (arg == "--cells") {
                perCell = true;
            } else if (arg == "--dt" && value) {
                dt = std::atof(argv[++a]);
            } else if (arg == "--sample" && value) {
                sampleInterval = std::atof(argv[++a]);
            } else if (arg == "--K0" && value) {
                K0 = std::atof(argv[++a]);
            } else if (arg == "--splitting" && value) {
                const std::string scheme = argv[++a];
                if (scheme != "Lie" && scheme != "Strang") {
                    std::fprintf(stderr, "ductReference: --splitting Lie or Strang, not %s\n",
                                 scheme.c_str());
                    return 2;
                }
                strang = scheme == "Strang";
            } else if (!(a == 4 && arg[0] != '-')) {
                std::fprintf(stderr, "ductReference: unknown or incomplete option %s\n",
                             arg.c_str());
                return 2;
            }
        }
        const double stepsPerSample = sampleInterval / dt;
        if (!(n > 0) || !(endTime > tRelax) || !(dt > 0) || !(u * dt <= dx)
            || std::abs(stepsPerSample - std::round(stepsPerSample)) > 1e-9 * stepsPerSample) {
            std::fprintf(stderr, "ductReference: need n > 0, endTime > %g, 0 < dt <= dx/u and "
                                 "sampleInterval %g a multiple of dt\n", tRelax, sampleInterval);
            return 2;
        }
        // The tutorial's V1 per algorithm; unit cross-section, so a cell's volume is dx
        const double V1 = algorithm == "SWA" ? 1.25e-8 : 1e-7;
        const double V = dx, W = V / (n * V1);

        auto kernel = coag::makeKernel("constant", K0);
        coag::InceptionModel inception;
        inception.rate = inceptionRate;
        inception.type.mass = 1.0;
        inception.weight = W;
        auto cellAlgorithm = coag::makeCellAlgorithm(algorithm, *kernel, inception, {});

        coag::Rng rng(seed);
        coag::StepStatistics stats;
        coag::CellPopulation population;
        population.volume = V;
        std::vector<DuctParticle> particles, moved;
        std::vector<std::vector<int>> inCell(nCells);
        std::vector<std::array<double, 4>> momentSum(nCells, {0, 0, 0, 0});
        long samples = 0;

        const long nSteps = std::lround(endTime / dt);
        const long sampleEvery = std::lround(sampleInterval / dt);
        // A over a time: every particle moves with u, what reaches x >= L leaves
        auto advect = [&](std::vector<DuctParticle>& from, double time) {
            particles.clear();
            for (const DuctParticle& p : from) {
                if (p.x + u * time < L) particles.push_back({p.x + u * time, p.mass, p.weight});
            }
        };
        for (long step = 1; step <= nSteps; ++step) {
            if (strang) {
                moved.swap(particles);
                advect(moved, 0.5 * dt);  // Strang's first half of A
            }
            for (auto& c : inCell) c.clear();
            for (int i = 0; i < static_cast<int>(particles.size()); ++i) {
                inCell[cellOf(particles[i].x)].push_back(i);
            }
            moved.clear();
            for (int c = 0; c < nCells; ++c) {
                population.particles.clear();
                for (const int i : inCell[c]) {
                    coag::Particle p;
                    p.type.mass = particles[i].mass;
                    p.weight = particles[i].weight;
                    p.tag = i;
                    population.particles.push_back(p);
                }
                cellAlgorithm->advance(population, dt, rng, stats);
                for (const coag::Particle& p : population.particles) {
                    // A survivor keeps its position; a new particle is uniform in the cell
                    const double x = p.tag >= 0 ? particles[p.tag].x : (c + rng.uniform()) * dx;
                    moved.push_back({x, p.type.mass, p.weight});
                }
            }
            advect(moved, strang ? 0.5 * dt : dt);
            if (step % sampleEvery == 0 && step * dt >= tRelax - 0.5 * dt) {
                ++samples;
                for (const DuctParticle& p : particles) {
                    double mk = p.weight / V;
                    for (int k = 0; k < 4; ++k, mk *= p.mass) momentSum[cellOf(p.x)][k] += mk;
                }
            }
        }

        std::array<double, 4> tail{0, 0, 0, 0};
        for (int c = 0; c < nCells; ++c) {
            for (int k = 0; k < 4; ++k) {
                const double exact =
                    (analyticIntegral(k, (c + 1) * dx) - analyticIntegral(k, c * dx)) / dx;
                const double rel = momentSum[c][k] / samples / exact - 1.0;
                if (c >= nCells - 20) tail[k] += rel / 20.0;
                if (perCell) std::printf("cell %2d M%d %+.3f%%\n", c, k, 100.0 * rel);
            }
        }
        std::printf("%s n=%g seed=%llu dt=%g %s samples=%ld particles=%zu events=%llu; mean "
                    "relative error over the last 20 cells: M0 %+.3f%% M1 %+.3f%% M2 %+.3f%% "
                    "M3 %+.3f%%\n",
                    algorithm.c_str(), n, seed, dt, strang ? "Strang" : "Lie", samples,
                    particles.size(),
                    static_cast<unsigned long long>(stats.coagulations), 100 * tail[0],
                    100 * tail[1], 100 * tail[2], 100 * tail[3]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ductReference: %s\n", e.what());
        return 1;
    }
    return 0;
}
