// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The Lagrangian reference of the coagulationFoam puff in frozen pseudo-turbulence:
// monomers of density S = 1 uniform in the cells of a uniform cube mesh whose centres lie in the
// ball |x| <= R (what topoSet's sphereToCell selects), Saffman-Turner kernel with K_11 = 1, and
// the field sample that pseudoTurbulenceField writes for the same (epsilon, eta, L, n0, n, seed).
// The direct estimator (3.14): x0 uniform in that union of cells, its forward trajectory in the
// analytic field, the homogeneous solution Phi(1; T) from the table; the domains are the unions
// of cells with centres in |x| <= r, so that coagulationFoam's cell fields sum over the same set.
//   pseudoTurbulencePuff [--epsilon 1 --eta 2 --L 24 --n0 4 --n 8 --seed 1 --half 12 --h 0.5
//                         --R 4 --T 2 --rate 1 --points 20000 --radii 2,4,6,8 --dt 0.02]
// CSV on stdout: r, In (estimate), In_se (standard error), In_v0 (no transport, exact), mass,
// mass_se.
#include "coagulationReferences/lagrangian/LagrangianCoagulation.hpp"
#include "coagulationReferences/pseudoTurbulence/PseudoTurbulence.hpp"
#include "coagulation/random/CounterStream.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace coag;

int main(int argc, char** argv)
{
    std::map<std::string, std::string> a{{"epsilon", "1"}, {"eta", "2"}, {"L", "24"}, {"n0", "4"},
        {"n", "8"}, {"seed", "1"}, {"half", "12"}, {"h", "0.5"}, {"R", "4"}, {"T", "2"},
        {"rate", "1"}, {"points", "20000"}, {"radii", "2,4,6,8"}, {"dt", "0.02"}};
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = std::string(argv[i]).substr(2);
        if (!a.count(k)) {
            std::cerr << "pseudoTurbulencePuff: unknown option " << argv[i] << "\n";
            return 2;
        }
        a[k] = argv[i + 1];
    }
    auto num = [&](const char* k) { return std::stod(a[k]); };
    PseudoTurbulenceParameters p;
    p.epsilon = num("epsilon");
    p.k0 = 2.0 * M_PI / num("L");
    p.kmax = 2.0 * M_PI / num("eta");
    p.logIntervals = std::stoi(a["n0"]);
    p.nPerInterval = std::stoi(a["n"]);
    p.check();
    const PseudoTurbulence field(p, std::stoull(a["seed"]));
    const VelocityField v = velocityField(field);
    const double half = num("half"), h = num("h"), R = num("R"), T = num("T"), rate = num("rate");
    std::vector<double> radii;
    {
        std::stringstream ss(a["radii"]);
        std::string item;
        while (std::getline(ss, item, ',')) radii.push_back(std::stod(item));
    }
    auto centre = [&](double x) { return (std::floor((x + half) / h) + 0.5) * h - half; };
    auto centreRadius2 = [&](const double x[3]) {
        double s = 0.0;
        for (int c = 0; c < 3; ++c) s += centre(x[c]) * centre(x[c]);
        return s;
    };

    SaffmanTurnerKernel kernel(1.0 / 8.0);
    const auto table = HomogeneousTable::fromOde(kernel, rate * T, 128, 200);
    InitialSource src{InitialSource::Profile::Uniform, Sphere{{{0.0, 0.0, 0.0}}, R + h}};
    LagrangianSolution sol(table, src, rate, 1);
    Score sc;
    sol.homogeneous(1.0, T, sc);   // every origin has S^I = 1

    // the source: cells with centres in |x| <= R, volume = count h^3
    const long nc = long(std::llround(2.0 * half / h));
    long sourceCells = 0;
    std::vector<long> v0(radii.size(), 0);
    for (long i = 0; i < nc; ++i)
        for (long j = 0; j < nc; ++j)
            for (long k = 0; k < nc; ++k) {
                const double c[3] = {(i + 0.5) * h - half, (j + 0.5) * h - half, (k + 0.5) * h - half};
                const double r2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
                if (r2 > R * R) continue;
                ++sourceCells;
                for (std::size_t q = 0; q < radii.size(); ++q)
                    if (r2 <= radii[q] * radii[q]) ++v0[q];
            }
    const double VD = double(sourceCells) * h * h * h;

    const std::size_t N = std::stoul(a["points"]);
    TrajectoryOptions o{TrajectoryScheme::RK4, num("dt")};
    CounterStream rng(0x5eed);
    const Sphere box{{{0.0, 0.0, 0.0}}, R + h};   // holds every source cell
    std::vector<double> s1(radii.size(), 0.0), s2(radii.size(), 0.0);
    std::size_t accepted = 0;
    while (accepted < N) {
        double x[3];
        box.sample(rng, x);
        if (centreRadius2(x) > R * R) continue;   // x0 uniform in the source cells
        ++accepted;
        forwardTrajectory(v, o, 0.0, T, x);         // (3.2)
        const double r2 = centreRadius2(x);
        for (std::size_t q = 0; q < radii.size(); ++q) {
            const double score = r2 <= radii[q] * radii[q] ? VD * sc.total : 0.0;   // (3.14)
            s1[q] += score;
            s2[q] += score * score;
        }
    }
    std::printf("r,In,In_se,In_v0,mass,mass_se\n");
    const double Nd = double(N), massPerNumber = sc.mass / sc.total;
    for (std::size_t q = 0; q < radii.size(); ++q) {
        const double m = s1[q] / Nd;
        const double se = std::sqrt(std::max(0.0, (s2[q] / Nd - m * m) / (Nd - 1.0)));
        std::printf("%g,%.8g,%.4g,%.8g,%.8g,%.4g\n", radii[q], m, se,
                    double(v0[q]) * h * h * h * sc.total, m * massPerNumber, se * massPerNumber);
    }
    std::fprintf(stderr, "pseudoTurbulencePuff: %d harmonics, u0 = %g, %ld source cells, "
                 "Phi_total(1; T) = %.6f\n", int(field.harmonics()), p.u0(), sourceCells, sc.total);
    return 0;
}
