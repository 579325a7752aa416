// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// plugFlowReference: the plug-flow (homogeneous, closed-cell) solution of a reactor's axis,
// the deterministic reference of tutorials/hotReactor.
//
// A parcel of gas moves along the axis with the axis's velocity U(x), through its
// temperature T(x) and pressure p(x) (sampled from a flow solver's fields); it carries
// monodisperse particles of mass 1 at the number density n0 it entered with and, nothing
// entering or leaving it, they coagulate by Brownian motion (coag::BrownianKernel, the
// regime given, on the parcel's T and p; mu by Sutherland's law of air) following the
// discrete Smoluchowski equation (coag::DiscreteSmoluchowski, sizes 1..L, integrated
// adaptively). The gas heats or cools at constant mass, so the number per unit mass of gas is
// what coagulation alone changes: the densities are scaled with the gas density p/T (ideal
// gas) between the points. The residence time is t(x) = int_0^x dx'/U(x'), by the trapezoid
// rule; each interval between consecutive points takes its mid T and p (the kernel matrix is
// rebuilt when the mid T has moved more than --dT kelvin from the one it was built on).
//
//   plugFlowReference AXISFILE OUTDIR --density RHO --massUnit MU --n0 N0
//                     [--L 1024] [--regime transition] [--probes x1,x2,...] [--dT 5]
//
// AXISFILE: whitespace columns x [m], T [K], p [Pa], U_x [m/s] along the axis (increasing x;
// the parcel enters at x = 0 with the first point's state). Writes OUTDIR/plugFlow.csv
// (x, t, T, p, M0 [m^-3], M1 [mass units m^-3], mean mass, d10 [nm], the diameter of the
// mean mass [nm], the fraction of the mass lost beyond size L) at every point and
// OUTDIR/plugFlowSizes.csv (x, mass, n [m^-3]) at each probe x (interpolated in the axis).
#include "coagulation/coagulation.hpp"
#include "coagulationReferences/smoluchowski/SmoluchowskiReference.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Point {
    double x, T, p, U;
};

std::vector<Point> readAxis(const std::string& path)
{
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error("cannot open " + path);
    }
    std::vector<Point> pts;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') {
            continue;
        }
        std::istringstream s(line);
        Point q{};
        if (s >> q.x >> q.T >> q.p >> q.U) {
            if (!(q.T > 0 && q.p > 0 && q.U > 0)) {
                throw std::runtime_error("non-positive T, p or U at x = " + std::to_string(q.x));
            }
            if (!pts.empty() && q.x <= pts.back().x) {
                throw std::runtime_error("x must increase in " + path);
            }
            pts.push_back(q);
        }
    }
    if (pts.size() < 2) {
        throw std::runtime_error("fewer than two points in " + path);
    }
    return pts;
}

Point interpolate(const std::vector<Point>& pts, double x)
{
    if (x <= pts.front().x) {
        Point q = pts.front();
        q.x = x;
        return q;
    }
    for (std::size_t i = 1; i < pts.size(); ++i) {
        if (x <= pts[i].x) {
            const Point& a = pts[i - 1];
            const Point& b = pts[i];
            const double w = (x - a.x) / (b.x - a.x);
            return {x, a.T + w * (b.T - a.T), a.p + w * (b.p - a.p), a.U + w * (b.U - a.U)};
        }
    }
    Point q = pts.back();
    q.x = x;
    return q;
}

std::vector<double> parseList(const char* s)
{
    std::vector<double> v;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ',')) {
        if (!item.empty()) {
            v.push_back(std::stod(item));
        }
    }
    return v;
}

int usage()
{
    std::fprintf(stderr,
                 "usage: plugFlowReference AXISFILE OUTDIR --density RHO --massUnit MU --n0 N0\n"
                 "       [--L 1024] [--regime transition] [--probes x1,x2,...] [--dT 5]\n");
    return 2;
}

} // namespace

int main(int argc, char** argv)
{
    try {
        if (argc < 3) {
            return usage();
        }
        const std::string axisFile = argv[1];
        const std::string outDir = argv[2];
        coag::ParticleMaterial material;
        material.density = -1;
        material.massUnit = -1;
        double n0 = -1, dTmax = 5.0;
        std::size_t L = 1024;
        coag::BrownianRegime regime = coag::BrownianRegime::transition;
        std::vector<double> probes;
        for (int a = 3; a < argc; ++a) {
            const std::string opt = argv[a];
            if (a + 1 >= argc) {
                return usage();
            }
            const char* v = argv[++a];
            if (opt == "--density") material.density = std::stod(v);
            else if (opt == "--massUnit") material.massUnit = std::stod(v);
            else if (opt == "--n0") n0 = std::stod(v);
            else if (opt == "--L") L = static_cast<std::size_t>(std::stoul(v));
            else if (opt == "--regime") regime = coag::parseBrownianRegime(v);
            else if (opt == "--probes") probes = parseList(v);
            else if (opt == "--dT") dTmax = std::stod(v);
            else return usage();
        }
        if (material.density <= 0 || material.massUnit <= 0 || !(n0 > 0)) {
            std::fprintf(stderr, "--density, --massUnit and --n0 are required and positive\n");
            return usage();
        }
        material.check();
        const std::vector<Point> axis = readAxis(axisFile);

        // The stations: every axis point and every probe, in order
        struct Station {
            double x;
            bool probe;
        };
        std::vector<Station> stations;
        for (const Point& q : axis) stations.push_back({q.x, false});
        for (double x : probes) stations.push_back({x, true});
        std::sort(stations.begin(), stations.end(),
                  [](const Station& a, const Station& b) { return a.x < b.x; });

        const Eigen::Index nL = static_cast<Eigen::Index>(L);
        Eigen::VectorXd n = Eigen::VectorXd::Zero(nL);
        n(0) = n0;
        Eigen::VectorXd mass(nL), diam(nL);
        for (Eigen::Index l = 0; l < nL; ++l) {
            mass(l) = static_cast<double>(l + 1);
            diam(l) = material.diameter(mass(l));
        }
        const double massPerGas0 = n0 / (axis.front().p / axis.front().T);  // M1 per p/T

        std::unique_ptr<coag::DiscreteSmoluchowski> ode;
        double kernelT = -1;
        auto gasAt = [](double T, double p) {
            coag::GasState g;
            g.T = T;
            g.p = p;
            g.mu = coag::sutherlandViscosity(T);
            return g;
        };

        std::ofstream out(outDir + "/plugFlow.csv");
        std::ofstream sizes(outDir + "/plugFlowSizes.csv");
        if (!out || !sizes) {
            throw std::runtime_error("cannot write to " + outDir);
        }
        out << "x,t,T,p,M0,M1,meanMass,d10_nm,dMeanMass_nm,lostMassFraction\n";
        sizes << "x,mass,n\n";
        out.precision(10);
        sizes.precision(10);

        Point prev = interpolate(axis, 0.0);
        double t = 0.0;
        std::size_t rebuilds = 0, steps = 0;
        for (const Station& s : stations) {
            const Point here = interpolate(axis, s.x);
            if (s.x > prev.x) {
                const double dt = (here.x - prev.x) * 0.5 * (1.0 / prev.U + 1.0 / here.U);
                const double Tm = 0.5 * (prev.T + here.T), pm = 0.5 * (prev.p + here.p);
                if (!ode || std::abs(Tm - kernelT) > dTmax) {
                    const coag::BrownianKernel kernel(regime, gasAt(Tm, pm), material);
                    ode = std::make_unique<coag::DiscreteSmoluchowski>(kernel, L);
                    ode->setTolerances(1e-7, 1e-12 * n0);
                    kernelT = Tm;
                    ++rebuilds;
                }
                // to the interval's mid gas density, coagulation over dt, to the end's density
                n *= (pm / Tm) / (prev.p / prev.T);
                n = ode->integrate(n, 0.0, dt);
                n = n.cwiseMax(0.0);
                n *= (here.p / here.T) / (pm / Tm);
                t += dt;
                ++steps;
            }
            prev = here;

            const double M0 = n.sum();
            const double M1 = n.dot(mass);
            const double rhoRel = here.p / here.T;
            const double lost = 1.0 - M1 / (massPerGas0 * rhoRel);
            const double d10 = n.dot(diam) / M0;
            const double dMean = material.diameter(M1 / M0);
            if (!s.probe) {
                out << here.x << ',' << t << ',' << here.T << ',' << here.p << ',' << M0 << ','
                    << M1 << ',' << M1 / M0 << ',' << d10 * 1e9 << ',' << dMean * 1e9 << ','
                    << lost << '\n';
            } else {
                for (Eigen::Index l = 0; l < nL; ++l) {
                    if (n(l) > 0) {
                        sizes << here.x << ',' << mass(l) << ',' << n(l) << '\n';
                    }
                }
                std::printf("probe x = %g m: t = %.5g s, T = %.1f K, M0 = %.4g m^-3, d10 = %.3f nm,"
                            " d(mean mass) = %.3f nm, mass beyond L = %.2e\n",
                            here.x, t, here.T, M0, d10 * 1e9, dMean * 1e9, lost);
            }
        }
        const Point last = axis.back();
        const double lostEnd = 1.0 - n.dot(mass) / (massPerGas0 * last.p / last.T);
        std::printf("plug flow along %zu points to x = %g m: residence time %.5g s, T %.1f -> %.1f K,"
                    " %zu intervals, %zu kernel matrices (L = %zu)\n",
                    axis.size(), last.x, t, axis.front().T, last.T, steps, rebuilds, L);
        if (lostEnd > 1e-3) {
            std::fprintf(stderr, "plugFlowReference: %.2e of the mass went beyond size L = %zu;"
                                 " raise --L\n", lostEnd, L);
            return 1;
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "plugFlowReference: %s\n", e.what());
        return 1;
    }
}
