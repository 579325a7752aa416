// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The Eulerian coagulation-diffusion reference of Sabelfeld-Kolodko §6 (Figs 3-5):
// n^E_l(t', 0) for l = 1..20 at t' = 1, 5, 10, K = 1, n0 = 1 on [-R, R]^2 (t' = t K11 n0,
// x' = x/R), D = 8.88e-2 R^2/T_c by default, and the wall time.
//
//   eulerianReference [--dx 0.07] [--dt 0.0125] [--W 2] [--gamma 1.1] [--Lambda 14000]
//                     [--D 0.0888] [--euler] [--zeroFlux] [--saffmanTurner] [--sizes 20]
//                     [--tmax 10]   (only the times t' <= tmax of 1, 5, 10)
//
// Output: a CSV "t,l,nE,nL,nE/nL" on stdout, a summary line (nodes, grid, steps, wall time) on
// stderr. nL is the Lagrangian model (9) in closed form for the constant kernel: with data
// uniform in G and v = 0, rho(t; n0) is the same for every x0 in G, so
// nL_l(t, x) = u_l(t) N^D(t, x), u the exact constant-kernel solution (README (30) form).
#include "coagulationReferences/coagulationDiffusion/CoagulationDiffusionReference.hpp"
#include "coagulationReferences/smoluchowski/ExactSolutions.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

int main(int argc, char** argv)
{
    coag::CoagulationDiffusionOptions o;
    std::size_t sizes = 20;
    double tmax = 10.0;
    bool st = false;
    for (int a = 1; a < argc; ++a) {
        const std::string k = argv[a];
        auto val = [&]() {
            if (a + 1 >= argc) {
                std::fprintf(stderr, "%s needs a value\n", k.c_str());
                std::exit(2);
            }
            return std::atof(argv[++a]);
        };
        if (k == "--dx") o.dx = val();
        else if (k == "--dt") o.dt = val();
        else if (k == "--W") o.halfWidth = val();
        else if (k == "--gamma") o.gamma = val();
        else if (k == "--Lambda") o.maxSize = static_cast<std::size_t>(val());
        else if (k == "--D") o.diffusion = val();
        else if (k == "--sizes") sizes = static_cast<std::size_t>(val());
        else if (k == "--tmax") tmax = val();
        else if (k == "--euler") o.scheme = coag::CoagulationDiffusionOptions::Scheme::Euler;
        else if (k == "--zeroFlux") o.boundary = coag::CoagulationDiffusionOptions::Boundary::ZeroFlux;
        else if (k == "--saffmanTurner") st = true;
        else {
            std::fprintf(stderr, "unknown option %s\n", k.c_str());
            return 2;
        }
    }
    std::unique_ptr<coag::CoagulationKernel> K;
    if (st) K = std::make_unique<coag::SaffmanTurnerKernel>(0.125);
    else K = std::make_unique<coag::ConstantKernel>(1.0);
    const auto t0 = std::chrono::steady_clock::now();
    coag::CoagulationDiffusion2D sol(*K, o);
    std::printf("t,l,nE,nL,nE/nL\n");
    for (double t : {1.0, 5.0, 10.0}) {
        if (t > tmax) break;
        sol.advanceTo(t);
        for (std::size_t l = 1; l <= sizes; ++l) {
            const double nE = sol.density(l, 0.0, 0.0);
            double nL = 0.0;
            if (!st) {  // K = 1
                nL = coag::exact::constantKernelDensity(1.0, o.n0, sol.time(), l)
                     * coag::exact::diffusedSquare(1.0, o.R, o.diffusion, sol.time(), 0.0, 0.0);
            }
            std::printf("%.6g,%zu,%.10g,%.10g,%.6g\n", sol.time(), l, nE, nL, nL > 0 ? nE / nL : 0.0);
        }
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::fprintf(stderr,
                 "eulerianReference: kernel %s, D %g, dx %g, dt %g, W %g (%zu^2 quadrant nodes), gamma %g, "
                 "Lambda %zu (%zu nodes, %zu gain entries), %s, %zu steps, total number %.8g, wall %.2f s\n",
                 K->name().c_str(), o.diffusion, o.dx, o.dt, o.halfWidth, sol.gridPoints(), o.gamma,
                 o.maxSize, sol.sizes().nNodes(), sol.sizes().nGainEntries(),
                 o.scheme == coag::CoagulationDiffusionOptions::Scheme::Heun ? "Heun" : "Euler",
                 sol.steps(), sol.totalNumber(), wall);
    return 0;
}
