// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The data of Sabelfeld-Kolodko's Figs 2-10 from the Lagrangian estimators
// (CoagulationDiffusionLagrangian.hpp) and the Eulerian reference (CoagulationDiffusionReference.hpp).
//
//   coagulationDiffusionFigures fig2      [--tmax 10] [--nt 201] [--N 20000] [--seed 1]
//       2-D, x = 0, n0 = 1, K = 1 (C = 1), D/R^2 = 2.22e-2, 8.88e-2, 3.55e-1, 1.42 (in R^2/T_c):
//       CSV "D,t,FR,F,F_hw": F_R (22)-(23) at every t', and the Monte Carlo F (20) with its 95 %
//       half-width at t' = 1..tmax (F, F_hw empty elsewhere).
//   coagulationDiffusionFigures figs3to8  [--tmax 10] [--nt 41] [--N 20000] [--sizes 20]
//                                         [--seed 1] [--noEulerian] [--W 4] [--dx 0.07]
//                                         [--dt 0.0125] [--gamma 1.1] [--Lambda 14000]
//       K = 1, n0 = 1 on [-R, R]^2, D = 8.88e-2: CSV "t,l,nL,nL_hw,nLexact,nE" at x = (0, 0):
//       nL by the adjoint point estimator (16)-(17) (N paths per time), nLexact = u_l(t') N^D
//       (closed form for these data), nE the Eulerian reference; wall times on stderr.
//   coagulationDiffusionFigures figs9to10 [--tmax 2] [--nt 41] [--N 20000] [--seed 1]
//       §7, Saffman-Turner K_ij = (i^1/3 + j^1/3)^3 / 8, units t' = t/T_D, x' = x/R (D' = 1):
//       CSV "x,b,t,ND,NCD,ND_est,ND_hw,NCD_est,NCD_hw" at x' = (0, 0) and (1.5, 0),
//       b = 0.01, 0.1, 1: N^D (29), N^CD = u_1(b t') N^D (30), and both by the adjoint estimator.
#include "coagulationReferences/coagulationDiffusion/CoagulationDiffusionLagrangian.hpp"
#include "coagulationReferences/coagulationDiffusion/CoagulationDiffusionReference.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0)
{
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Args {
    std::map<std::string, double> v;
    double get(const std::string& k, double d) const
    {
        auto it = v.find(k);
        return it == v.end() ? d : it->second;
    }
    bool has(const std::string& k) const { return v.count(k) != 0; }
};

int fig2(const Args& a)
{
    const double tmax = a.get("tmax", 10.0);
    const int nt = static_cast<int>(a.get("nt", 201));
    const std::size_t N = static_cast<std::size_t>(a.get("N", 20000));
    const std::uint64_t seed = static_cast<std::uint64_t>(a.get("seed", 1));
    coag::ConstantKernel K(1.0);
    const auto t0 = Clock::now();
    const coag::HomogeneousTable table = coag::table18(K, 300, tmax, 20, 400);
    const double C = coag::kernelBoundConstant(K, 100);
    const double x[2] = {0.0, 0.0};
    std::printf("D,t,FR,F,F_hw\n");
    for (double D : {2.22e-2, 8.88e-2, 3.55e-1, 1.42}) {
        coag::DiffusionProcess p;
        p.dim = 2;
        p.D = D;
        coag::MonodisperseData data;
        data.support = coag::Box::centred(2, 1.0);
        coag::LagrangianEstimator est(table, p, data);
        for (int k = 0; k < nt; ++k) {
            const double t = tmax * k / (nt - 1);
            const double FR = coag::effectiveSourceBound(2, 1.0, C, 1.0, D, t, x);  // (22)
            const bool integer = k > 0 && std::abs(t - std::round(t)) < 1e-9;
            if (integer) {
                const coag::EffectiveSource F = est.effectiveSource(t, x, N, seed + k);  // (20)
                std::printf("%g,%.6g,%.8g,%.8g,%.3g\n", D, t, FR, F.F, F.halfWidth);
            } else {
                std::printf("%g,%.6g,%.8g,,\n", D, t, FR);
            }
        }
    }
    std::fprintf(stderr, "fig2: wall %.2f s (N = %zu per Monte Carlo F)\n", since(t0), N);
    return 0;
}

int figs3to8(const Args& a)
{
    const double tmax = a.get("tmax", 10.0);
    const int nt = static_cast<int>(a.get("nt", 41));
    const std::size_t N = static_cast<std::size_t>(a.get("N", 20000));
    const std::size_t sizes = static_cast<std::size_t>(a.get("sizes", 20));
    const std::uint64_t seed = static_cast<std::uint64_t>(a.get("seed", 1));
    const double D = 8.88e-2;
    coag::ConstantKernel K(1.0);
    std::vector<double> times;
    for (int k = 1; k < nt; ++k) times.push_back(tmax * k / (nt - 1));
    // Lagrangian: one table of (18), the adjoint point estimator at each time
    const auto tl = Clock::now();
    const coag::HomogeneousTable table = coag::table18(K, 400, tmax, sizes, 400);
    coag::DiffusionProcess p;
    p.dim = 2;
    p.D = D;
    coag::MonodisperseData data;
    data.support = coag::Box::centred(2, 1.0);
    coag::LagrangianEstimator est(table, p, data);
    const double x[2] = {0.0, 0.0};
    std::vector<coag::Estimate> nL;
    for (std::size_t k = 0; k < times.size(); ++k)
        nL.push_back(est.adjointPoint(times[k], x, N, seed + k));
    const double wallL = since(tl);
    // Eulerian reference at the same times
    std::vector<std::vector<double>> nE(times.size());
    double wallE = 0.0;
    coag::CoagulationDiffusionOptions o;
    o.diffusion = D;
    o.halfWidth = a.get("W", 4.0);
    o.dx = a.get("dx", 0.07);
    o.dt = a.get("dt", 0.0125);
    o.gamma = a.get("gamma", 1.1);
    o.maxSize = static_cast<std::size_t>(a.get("Lambda", 14000));
    if (!a.has("noEulerian")) {
        const auto te = Clock::now();
        coag::CoagulationDiffusion2D sol(K, o);
        for (std::size_t k = 0; k < times.size(); ++k) {
            sol.advanceTo(times[k]);
            for (std::size_t l = 1; l <= sizes; ++l) nE[k].push_back(sol.density(l, 0.0, 0.0));
        }
        wallE = since(te);
    }
    std::printf("t,l,nL,nL_hw,nLexact,nE\n");
    for (std::size_t k = 0; k < times.size(); ++k)
        for (std::size_t l = 1; l <= sizes; ++l) {
            const double exact =
                table.density(l, times[k]) * coag::exact::diffusedSquare(1.0, 1.0, D, times[k], 0, 0);
            std::printf("%.6g,%zu,%.8g,%.3g,%.8g,", times[k], l, nL[k].mean[l - 1],
                        nL[k].halfWidth[l - 1], exact);
            if (nE[k].empty()) std::printf("\n");
            else std::printf("%.8g\n", nE[k][l - 1]);
        }
    std::fprintf(stderr,
                 "figs3to8: %zu times, sizes 1..%zu; Lagrangian (N = %zu paths a time) wall %.2f s; "
                 "Eulerian (W %g, dx %g, dt %g, gamma %g, Lambda %zu) wall %.2f s%s\n",
                 times.size(), sizes, N, wallL, o.halfWidth, o.dx, o.dt, o.gamma, o.maxSize, wallE,
                 a.has("noEulerian") ? " (not run)" : "");
    return 0;
}

int figs9to10(const Args& a)
{
    const double tmax = a.get("tmax", 2.0);
    const int nt = static_cast<int>(a.get("nt", 41));
    const std::size_t N = static_cast<std::size_t>(a.get("N", 20000));
    const std::uint64_t seed = static_cast<std::uint64_t>(a.get("seed", 1));
    const auto t0 = Clock::now();
    coag::ConstantKernel none(1e-12);  // "no coagulation": u_1 = 1 to 1e-11
    const coag::HomogeneousTable diffusionOnly = coag::table18(none, 10, tmax, 1, 10);
    coag::DiffusionProcess p;
    p.dim = 2;
    p.D = 1.0;  // t' = t/T_D, x' = x/R
    coag::MonodisperseData data;
    data.support = coag::Box::centred(2, 1.0);
    std::printf("x,b,t,ND,NCD,ND_est,ND_hw,NCD_est,NCD_hw\n");
    std::uint64_t stream = 0;
    for (double xp : {0.0, 1.5}) {
        const double x[2] = {xp, 0.0};
        for (double b : {0.01, 0.1, 1.0}) {
            coag::SaffmanTurnerKernel K(b / 8.0);  // K_ij = b (i^1/3 + j^1/3)^3 / 8 in T_D units
            const coag::HomogeneousTable table = coag::table18(K, 200, tmax, 1, 400);
            coag::LagrangianEstimator eCD(table, p, data), eD(diffusionOnly, p, data);
            for (int k = 1; k < nt; ++k) {
                const double t = tmax * k / (nt - 1);
                const double ND = coag::exact::diffusedSquare(1.0, 1.0, 1.0, t, xp, 0.0);  // (29)
                const double NCD = table.density(1, t) * ND;  // (30)
                // independent paths for every estimate (N^D is estimated anew for each b)
                const coag::Estimate d = eD.adjointPoint(t, x, N, seed * 1000003 + stream++);
                const coag::Estimate c = eCD.adjointPoint(t, x, N, seed * 1000003 + stream++);
                std::printf("%g,%g,%.6g,%.8g,%.8g,%.8g,%.3g,%.8g,%.3g\n", xp, b, t, ND, NCD,
                            d.mean[0], d.halfWidth[0], c.mean[0], c.halfWidth[0]);
            }
        }
    }
    std::fprintf(stderr, "figs9to10: wall %.2f s (N = %zu paths per point)\n", since(t0), N);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s fig2|figs3to8|figs9to10 [--option value ...]\n", argv[0]);
        return 2;
    }
    const std::string mode = argv[1];
    Args a;
    for (int i = 2; i < argc; ++i) {
        std::string k = argv[i];
        if (k.rfind("--", 0) != 0) {
            std::fprintf(stderr, "bad argument %s\n", k.c_str());
            return 2;
        }
        k = k.substr(2);
        if (k == "noEulerian") {
            a.v[k] = 1;
            continue;
        }
        if (i + 1 >= argc) {
            std::fprintf(stderr, "--%s needs a value\n", k.c_str());
            return 2;
        }
        a.v[k] = std::atof(argv[++i]);
    }
    if (mode == "fig2") return fig2(a);
    if (mode == "figs3to8") return figs3to8(a);
    if (mode == "figs9to10") return figs9to10(a);
    std::fprintf(stderr, "unknown mode %s\n", mode.c_str());
    return 2;
}
