// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The §5 studies of Kolodko, Sabelfeld and Wagner: coagulation of monomers released in
// a ball D of radius R' in Kolmogorov pseudo-turbulence (5.11)-(5.16), with the Saffman-Turner
// kernel (5.2) through the table of the normalised problem (2.32), against the deterministic
// case (5.3). Kolmogorov units: x' = x/eta, t' = t/tau_eta, epsilon' = 1, kmax = 2 pi, k0 =
// 2 pi / L'; the table is read at beta s0 t' ((5.17)-(5.25) write f_l(beta t')).
//
//   lagrangianStudy --study uniform|linear --out DIR [options]
//     --times 1.25,55       t' values
//     --radii LIST          r' of the functionals-against-r' files (Figs 1-2, 7-8)
//     --sp-radii LIST       r' of the size-spectrum files (Figs 3-6)
//     --method direct|adjoint   direct (3.14): one set of forward trajectories from D serves every
//                           radius; adjoint (4.3)-(4.4): backward trajectories from points in each
//                           Omega_r (default: direct for uniform, adjoint for linear)
//     --realisations R      independent samples of the velocity field (4.5)
//     --points N            trajectories per realisation (per radius for the adjoint method)
//     --points-at r:N,...   the adjoint method's points for the given radii (small balls at late
//                           times, which few backward trajectories reach from D, need more)
//     --sizes n             sizes in the spectrum files
//     --beta 0.0039 --L 1000 --R 100   the paper's parameters
//     --n0 4 --n 8          log parts and harmonics per part of the field (5.15)
//     --dt 0.05 --scheme RK4   trajectory step (t') and scheme (Euler, Heun, RK4)
//     --seed S
// Files in DIR: functionals_t<t>.csv (r, In, Ms: stochastic mean, 95 % half-width, deterministic),
// spectrum_t<t>_r<r>.csv (l, Sp and In_l likewise), timing.csv; a summary on stdout.
// <Sp_l> = <In_l>/<In> and <Ms> = <mass>/<In> over all realisations (ExpectationFunctionals);
// the columns *_perRealisation hold the mean of each realisation's own ratio over the
// realisations with a cluster in Omega_r (not the paper's functional; kept for comparison).
#include "coagulationReferences/lagrangian/LagrangianCoagulation.hpp"
#include "coagulationReferences/pseudoTurbulence/PseudoTurbulence.hpp"
#include "coagulation/random/SplitMix64.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <string>
#include <vector>

using namespace coag;

namespace {

std::vector<double> parseList(const std::string& s)
{
    std::vector<double> v;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ',')) v.push_back(std::stod(item));
    return v;
}

std::string fmt(double x)
{
    std::ostringstream os;
    os << x;
    return os.str();
}

std::uint64_t mix(std::uint64_t a, std::uint64_t b)
{
    return coag::splitMix64Finalise(a * coag::splitMix64Golden + b + 0x632BE59BD9B4E019ULL);
}

// Per radius: the functionals of the expectations (the paper's <In>, <Ms> = <mass>/<In>,
// <Sp_l> = <In_l>/<In>), and for comparison the mean of each realisation's ratios over the
// realisations with a cluster in Omega_r (a biased estimator with few points per realisation)
struct RadiusStats {
    ExpectationFunctionals expect;
    RealisationStatistics ratio;
};

} // namespace

int main(int argc, char** argv)
{
    std::map<std::string, std::string> a{{"study", "uniform"}, {"out", "."}, {"times", "1.25,55"},
        {"radii", ""}, {"sp-radii", "10,100"}, {"method", ""}, {"realisations", "16"},
        {"points", "500"}, {"points-at", ""}, {"sizes", "20"}, {"beta", "0.0039"}, {"L", "1000"}, {"R", "100"},
        {"n0", "4"}, {"n", "8"}, {"dt", "0.05"}, {"scheme", "RK4"}, {"seed", "2026"}};
    for (int i = 1; i < argc; ++i) {
        std::string k = argv[i];
        if (k == "-h" || k == "--help") {
            std::cout << "see the comment at the top of applications/studies/lagrangianStudy/lagrangianStudy.cpp\n";
            return 0;
        }
        if (k.rfind("--", 0) != 0 || i + 1 >= argc || !a.count(k.substr(2))) {
            std::cerr << "lagrangianStudy: bad option " << k << "\n";
            return 2;
        }
        a[k.substr(2)] = argv[++i];
    }
    try {
        const bool linear = a["study"] == "linear";
        if (!linear && a["study"] != "uniform") throw std::invalid_argument("--study uniform|linear");
        const std::string method = a["method"].empty() ? (linear ? "adjoint" : "direct") : a["method"];
        if (method != "direct" && method != "adjoint") throw std::invalid_argument("--method direct|adjoint");
        const std::vector<double> times = parseList(a["times"]);
        const double beta = std::stod(a["beta"]), Lp = std::stod(a["L"]), Rp = std::stod(a["R"]);
        std::vector<double> radii = a["radii"].empty() ? std::vector<double>{} : parseList(a["radii"]);
        if (radii.empty())
            for (int i = 1; i <= 40; ++i) radii.push_back(Rp * 0.1 * i);   // 0.1 R' .. 4 R'
        const std::vector<double> spRadii = parseList(a["sp-radii"]);
        const int R = std::stoi(a["realisations"]);
        const std::size_t N = std::stoul(a["points"]), nSizes = std::stoul(a["sizes"]);
        TrajectoryOptions o{trajectorySchemeFromName(a["scheme"]), std::stod(a["dt"])};
        const std::uint64_t seed = std::stoull(a["seed"]);
        std::map<double, std::size_t> pointsAt;
        {
            std::stringstream ss(a["points-at"]);
            std::string item;
            while (std::getline(ss, item, ',')) {
                const auto colon = item.find(':');
                if (colon == std::string::npos) throw std::invalid_argument("--points-at r:N,...");
                pointsAt[std::stod(item.substr(0, colon))] = std::stoul(item.substr(colon + 1));
            }
        }

        PseudoTurbulenceParameters pp;
        pp.epsilon = 1.0;
        pp.kmax = 2.0 * M_PI;
        pp.k0 = 2.0 * M_PI / Lp;
        pp.logIntervals = std::stoi(a["n0"]);
        pp.nPerInterval = std::stoi(a["n"]);
        pp.check();

        // all radii the run needs: the functionals' and the spectra's
        // (a spectrum radius that is also a functionals radius reuses its estimates)
        std::vector<double> all = radii;
        std::vector<std::size_t> spIndex;
        for (double r : spRadii) {
            std::size_t k = 0;
            while (k < all.size() && all[k] != r) ++k;
            if (k == all.size()) all.push_back(r);
            spIndex.push_back(k);
        }

        double tMax = 0.0;
        for (double t : times) tMax = std::max(tMax, t);
        SaffmanTurnerKernel kernel(1.0 / 8.0);   // normalised: k_11 = 1 (2.32)
        const auto t0 = std::chrono::steady_clock::now();
        const std::size_t L = std::max<std::size_t>(64, nSizes);
        const auto table = HomogeneousTable::fromOde(kernel, beta * tMax, L, 400);
        const double tableSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        InitialSource src{linear ? InitialSource::Profile::Linear : InitialSource::Profile::Uniform,
                          Sphere{{{0.0, 0.0, 0.0}}, Rp}};
        LagrangianSolution sol(table, src, beta, nSizes);

        std::ofstream timing(a["out"] + "/timing.csv");
        timing << "t,method,realisations,trajectories,wall_s,trajectories_per_s,cpu_s,trajectories_per_cpu_s,harmonics,dt,scheme\n";
        std::printf("table: Saffman-Turner, %zu sizes, s in [0, %g], 401 nodes, %.3f s, lost mass %.2e\n",
                    L, beta * tMax, tableSeconds, table.lostMass());

        for (double t : times) {
            std::vector<RadiusStats> st(all.size());
            std::size_t trajectories = 0;
            const auto start = std::chrono::steady_clock::now();
            const std::clock_t cpu0 = std::clock();
            for (int r = 0; r < R; ++r) {
                PseudoTurbulence field(pp, mix(seed, std::uint64_t(r)));
                const VelocityField v = velocityField(field);
                std::vector<IntegralEstimate> est;
                if (method == "direct") {
                    std::vector<Sphere> omegas;
                    for (double rad : all) omegas.push_back(Sphere{{{0.0, 0.0, 0.0}}, rad});
                    est = directIntegrals(v, o, sol, t, omegas, N, mix(seed + 1, std::uint64_t(r)));
                    trajectories += N;
                } else {
                    for (std::size_t k = 0; k < all.size(); ++k) {
                        const std::size_t Nk = pointsAt.count(all[k]) ? pointsAt[all[k]] : N;
                        est.push_back(adjointIntegral(v, o, sol, t, Sphere{{{0.0, 0.0, 0.0}}, all[k]},
                                                      Nk, mix(seed + 2 + k, std::uint64_t(r))));
                        trajectories += Nk;
                    }
                }
                for (std::size_t k = 0; k < all.size(); ++k) {
                    const SphereFunctionals f = functionals(est[k]);
                    st[k].expect.add(est[k]);
                    if (est[k].total > 0.0) st[k].ratio.add(f.flatten());
                }
            }
            const double wall =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
            timing << t << "," << method << "," << R << "," << trajectories << "," << wall << ","
                   << double(trajectories) / wall << "," << cpu << "," << double(trajectories) / cpu << "," << pp.logIntervals * pp.nPerInterval << ","
                   << o.maxStep << "," << trajectorySchemeName(o.scheme) << "\n";
            std::printf("t' = %g: %s, %d realisations, %zu trajectories in %.2f s wall (%.0f /s), "
                        "%.2f s CPU (%.0f /s)\n", t, method.c_str(), R, trajectories, wall,
                        double(trajectories) / wall, cpu, double(trajectories) / cpu);

            auto summary = [&](std::size_t k) {
                const SphereFunctionals m = st[k].expect.mean();
                const SphereFunctionals h = st[k].expect.halfWidth95();
                SphereFunctionals mr = m, hr = h;   // the per-realisation ratios' mean
                if (st[k].ratio.count() > 0) {
                    mr = SphereFunctionals::unflatten(st[k].ratio.mean());
                    hr = SphereFunctionals::unflatten(st[k].ratio.halfWidth95());
                }
                return std::make_tuple(m, h, mr, hr, deterministicFunctionals(sol, t, all[k]));
            };
            std::ofstream fr(a["out"] + "/functionals_t" + fmt(t) + ".csv");
            fr << "r,In,In_hw,In_det,Ms,Ms_hw,Ms_det,ratio_realisations,Ms_perRealisation,Ms_perRealisation_hw\n";
            for (std::size_t k = 0; k < radii.size(); ++k) {
                auto [m, h, mr, hr, d] = summary(k);
                fr << all[k] << "," << m.In << "," << h.In << "," << d.In << "," << m.Ms << ","
                   << h.Ms << "," << d.Ms << "," << st[k].ratio.count() << "," << mr.Ms << ","
                   << hr.Ms << "\n";
            }
            for (std::size_t k : spIndex) {
                auto [m, h, mr, hr, d] = summary(k);
                std::ofstream fs(a["out"] + "/spectrum_t" + fmt(t) + "_r" + fmt(all[k]) + ".csv");
                fs << "l,Sp,Sp_hw,Sp_det,In_l,In_l_hw,In_l_det,Sp_perRealisation,Sp_perRealisation_hw\n";
                for (std::size_t l = 0; l < nSizes; ++l)
                    fs << l + 1 << "," << m.Sp[l] << "," << h.Sp[l] << "," << d.Sp[l] << ","
                       << m.In_l[l] << "," << h.In_l[l] << "," << d.In_l[l] << "," << mr.Sp[l]
                       << "," << hr.Sp[l] << "\n";
                std::printf("  r' = %g: In/S %.4g +- %.2g (det %.4g), Ms %.6f +- %.1e (det %.6f), "
                            "Sp_2/det %.3f +- %.3f, Sp_5/det %.3f +- %.3f, Sp_10/det %.3f +- %.3f "
                            "(mean of per-realisation ratios, %zu realisations with clusters: "
                            "Sp_5/det %.3f, Sp_10/det %.3f)\n",
                            all[k], m.In, h.In, d.In, m.Ms, h.Ms, d.Ms, m.Sp[1] / d.Sp[1],
                            h.Sp[1] / d.Sp[1], m.Sp[4] / d.Sp[4], h.Sp[4] / d.Sp[4],
                            nSizes >= 10 ? m.Sp[9] / d.Sp[9] : 0.0,
                            nSizes >= 10 ? h.Sp[9] / d.Sp[9] : 0.0, st[k].ratio.count(),
                            mr.Sp[4] / d.Sp[4], nSizes >= 10 ? mr.Sp[9] / d.Sp[9] : 0.0);
            }
        }
    } catch (const std::exception& e) {
        std::cerr << "lagrangianStudy: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
