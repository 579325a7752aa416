// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// brownianReference: the homogeneous (closed-cell) solution of the Smoluchowski equation
// with the Brownian kernel of a gas at each given temperature, from N0 particles of mass 1
// (one massUnit),
// by the converged sectional reference (SectionalSmoluchowski, cell average, 16 sections
// per mass doubling above the discrete sizes). The reference of a cell of a mesh whose
// temperature varies, and of a run at rest in one cell.
//
//   brownianReference -regime transition -T "300 600 900" -p 1e5 -density 1800
//                     -massUnit 9.42e-22 -N0 1e17 -times "0.005 0.01"
//
// prints CSV: T,time,M0,M1,M2 (per m3, masses in massUnit). The gas is air (molar mass
// 0.0289647 kg/mol) with Sutherland's viscosity (As 1.458e-6, Ts 110.4), as the solver's
// default. Exits 1 when the grid loses more than 1e-9 of the mass.
#include "coagulation/kernels/BrownianKernel.hpp"
#include "coagulationReferences/smoluchowski/SectionalSmoluchowski.hpp"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    std::map<std::string, std::string> opt{{"-regime", "transition"}, {"-T", "298.15"},
                                           {"-p", "101325"}, {"-density", "1000"},
                                           {"-massUnit", "1"},
                                           {"-N0", "1e17"}, {"-times", "1"}};
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!opt.count(argv[i])) {
            std::fprintf(stderr, "brownianReference: unknown option %s\n", argv[i]);
            return 2;
        }
        opt[argv[i]] = argv[i + 1];
    }
    auto list = [](const std::string& s) {
        std::vector<double> v;
        std::istringstream is(s);
        for (double x; is >> x;) v.push_back(x);
        return v;
    };
    try {
        const coag::BrownianRegime regime = coag::parseBrownianRegime(opt["-regime"]);
        coag::ParticleMaterial material;
        material.density = std::stod(opt["-density"]);
        material.massUnit = std::stod(opt["-massUnit"]);
        const double N0 = std::stod(opt["-N0"]);
        const std::vector<double> times = list(opt["-times"]);
        std::printf("T,time,M0,M1,M2\n");
        for (double T : list(opt["-T"])) {
            coag::GasState gas;
            gas.T = T;
            gas.p = std::stod(opt["-p"]);
            gas.mu = coag::sutherlandViscosity(T);
            const coag::BrownianKernel kernel(regime, gas, material);
            // masses in massUnit, the start's: the discrete sizes 1..16, then sections
            coag::SectionalSmoluchowski ode(kernel, coag::discreteGeometricGrid(1e6, 16));
            ode.setTolerances(1e-9, 1e-14 * N0);
            Eigen::VectorXd n = ode.monodisperse(N0, 1.0);
            double t = 0.0;
            for (double ti : times) {
                n = ode.integrate(n, t, ti);
                t = ti;
                const double M1 = ode.moment(n, 1);
                if (ode.lostMass() > 1e-9 * M1) {
                    std::fprintf(stderr, "brownianReference: the grid lost %g of the mass\n",
                                 ode.lostMass() / M1);
                    return 1;
                }
                std::printf("%.17g,%.17g,%.17g,%.17g,%.17g\n", T, ti, ode.moment(n, 0), M1,
                            ode.moment(n, 2));
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "brownianReference: %s\n", e.what());
        return 2;
    }
    return 0;
}
