// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulationReferences/pseudoTurbulence/Trajectory.hpp"
#include "coagulationReferences/pseudoTurbulence/PseudoTurbulence.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {

VelocityField velocityField(const PseudoTurbulence& field)
{
    const PseudoTurbulence* f = &field;
    return [f](double, const double x[3], double u[3]) { f->velocity(x, u); };
}

VelocityField uniformVelocity(double cx, double cy, double cz)
{
    return [cx, cy, cz](double, const double*, double u[3]) {
        u[0] = cx;
        u[1] = cy;
        u[2] = cz;
    };
}

TrajectoryScheme trajectorySchemeFromName(const std::string& name)
{
    if (name == "Euler") return TrajectoryScheme::Euler;
    if (name == "Heun") return TrajectoryScheme::Heun;
    if (name == "RK4") return TrajectoryScheme::RK4;
    throw std::invalid_argument("coag::trajectorySchemeFromName: unknown scheme '" + name +
                                "' (Euler, Heun, RK4)");
}

std::string trajectorySchemeName(TrajectoryScheme s)
{
    switch (s) {
    case TrajectoryScheme::Euler: return "Euler";
    case TrajectoryScheme::Heun: return "Heun";
    case TrajectoryScheme::RK4: return "RK4";
    }
    return "?";
}

int trajectorySchemeOrder(TrajectoryScheme s)
{
    switch (s) {
    case TrajectoryScheme::Euler: return 1;
    case TrajectoryScheme::Heun: return 2;
    case TrajectoryScheme::RK4: return 4;
    }
    return 0;
}

std::size_t TrajectoryOptions::steps(double T) const
{
    if (!(maxStep > 0.0) || !(T >= 0.0) || !std::isfinite(T)) {
        std::ostringstream os;
        os << "coag::TrajectoryOptions: need maxStep > 0 and a finite T >= 0, got maxStep = "
           << maxStep << ", T = " << T;
        throw std::invalid_argument(os.str());
    }
    return T == 0.0 ? 0 : std::size_t(std::ceil(T / maxStep * (1.0 - 1e-12)));
}

namespace {

template <class F>
inline void stepImpl(const F& v, TrajectoryScheme scheme, double t, double h, double x[3])
{
    double k1[3], k2[3], k3[3], k4[3], y[3];
    v(t, x, k1);
    switch (scheme) {
    case TrajectoryScheme::Euler:
        for (int c = 0; c < 3; ++c) x[c] += h * k1[c];
        return;
    case TrajectoryScheme::Heun:
        for (int c = 0; c < 3; ++c) y[c] = x[c] + h * k1[c];
        v(t + h, y, k2);
        for (int c = 0; c < 3; ++c) x[c] += 0.5 * h * (k1[c] + k2[c]);
        return;
    case TrajectoryScheme::RK4:
        for (int c = 0; c < 3; ++c) y[c] = x[c] + 0.5 * h * k1[c];
        v(t + 0.5 * h, y, k2);
        for (int c = 0; c < 3; ++c) y[c] = x[c] + 0.5 * h * k2[c];
        v(t + 0.5 * h, y, k3);
        for (int c = 0; c < 3; ++c) y[c] = x[c] + h * k3[c];
        v(t + h, y, k4);
        for (int c = 0; c < 3; ++c) x[c] += h / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
        return;
    }
}

} // namespace

void trajectoryStep(const VelocityField& v, TrajectoryScheme scheme, double t, double h, double x[3])
{
    stepImpl(v, scheme, t, h, x);
}

void forwardTrajectory(const VelocityField& v, const TrajectoryOptions& o, double t0, double T,
                       double x[3])
{
    const std::size_t M = o.steps(T);
    if (M == 0) return;
    const double h = T / double(M);
    for (std::size_t i = 0; i < M; ++i) stepImpl(v, o.scheme, t0 + double(i) * h, h, x);   // (3.2)
}

std::vector<std::array<double, 3>> forwardPath(const VelocityField& v, const TrajectoryOptions& o,
                                               double T, const double xStar[3])
{
    const std::size_t M = o.steps(T);
    std::vector<std::array<double, 3>> path(M + 1);
    double x[3] = {xStar[0], xStar[1], xStar[2]};
    path[0] = {x[0], x[1], x[2]};
    const double h = M ? T / double(M) : 0.0;
    for (std::size_t i = 0; i < M; ++i) {
        stepImpl(v, o.scheme, double(i) * h, h, x);   // (4.1)
        path[i + 1] = {x[0], x[1], x[2]};
    }
    return path;
}

void backwardTrajectory(const VelocityField& v, const TrajectoryOptions& o, double t, double x[3])
{
    const std::size_t M = o.steps(t);
    if (M == 0) return;
    const double h = t / double(M);
    // (3.6)/(4.2): dX*/dtau = -v(t - tau, X*)
    auto reversed = [&v, t](double tau, const double* y, double* u) {
        v(t - tau, y, u);
        for (int c = 0; c < 3; ++c) u[c] = -u[c];
    };
    for (std::size_t i = 0; i < M; ++i) stepImpl(reversed, o.scheme, double(i) * h, h, x);
}

} // namespace coag
