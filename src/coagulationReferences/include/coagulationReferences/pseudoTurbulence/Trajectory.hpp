// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_TRAJECTORY_HPP
#define COAGULATION_TRAJECTORY_HPP

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace coag {

class PseudoTurbulence;

//- A velocity field v(t, x) -> u (Kolodko-Sabelfeld-Wagner §3: incompressible; the integrators
//  do not check it).
using VelocityField = std::function<void(double t, const double x[3], double u[3])>;

//- A frozen sample of the pseudo-turbulence (5.14) as a VelocityField (holds a reference).
VelocityField velocityField(const PseudoTurbulence& field);
//- v = c (uniform translation)
VelocityField uniformVelocity(double cx, double cy, double cz);

//- Schemes for dX/dt = v(t, X): explicit Euler (the paper's baseline, §4.1 "say, using the
//  Euler scheme", order 1), Heun (explicit trapezoidal rule, order 2), classical Runge-Kutta
//  (order 4). Names: "Euler", "Heun", "RK4".
enum class TrajectoryScheme { Euler, Heun, RK4 };
TrajectoryScheme trajectorySchemeFromName(const std::string& name);
std::string trajectorySchemeName(TrajectoryScheme s);
int trajectorySchemeOrder(TrajectoryScheme s);

struct TrajectoryOptions {
    TrajectoryScheme scheme = TrajectoryScheme::RK4;
    double maxStep = 0.05;   //- largest time step; a time span T takes ceil(T / maxStep) equal steps
    std::size_t steps(double T) const;
};

//- One step of dX/dt = v(t, X) from (t, x) to t + h.
void trajectoryStep(const VelocityField& v, TrajectoryScheme scheme, double t, double h, double x[3]);

//- Forward trajectory (3.2)/(4.1): x holds X(t0) on entry and X(t0 + T) on return.
void forwardTrajectory(const VelocityField& v, const TrajectoryOptions& o, double t0, double T,
                       double x[3]);

//- Forward path (4.1): X(tau_i, x*) at tau_i = i T/M, i = 0..M, M = o.steps(T) (the §4.1 mesh).
std::vector<std::array<double, 3>> forwardPath(const VelocityField& v, const TrajectoryOptions& o,
                                               double T, const double xStar[3]);

//- Backward trajectory (3.6)/(4.2): dX*/dtau = -v(t - tau, X*), X*(0) = x, tau in [0, t]; x holds
//  the arrival point at time t on entry and X*(t, x), the trajectory's origin at time 0, on
//  return (for a steady v this is (4.2), dX*/dtau = -v(X*)).
void backwardTrajectory(const VelocityField& v, const TrajectoryOptions& o, double t, double x[3]);

} // namespace coag

#endif
