// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/growth/GrowthLaw.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {

double fuchsSutugin(double Kn, double alpha)
{
    const double r = 4.0 / (3.0 * alpha);
    return (1.0 + Kn) / (1.0 + (r + 0.377) * Kn + r * Kn * Kn);
}

void GrowthLaw::addPower(double c, double q)
{
    if (!std::isfinite(c) || !std::isfinite(q) || q > 1.0) {
        std::ostringstream os;
        os << "coag::GrowthLaw::addPower: the coefficient must be finite and the exponent "
              "<= 1, got dm/dt = "
           << c << " m^" << q;
        throw std::invalid_argument(os.str());
    }
    if (c == 0.0) return;
    for (Power& p : powers_) {
        if (p.q == q) {
            p.c += c;
            return;
        }
    }
    powers_.push_back({c, q});
}

void GrowthLaw::addTransition(double a, double b, double lambda, double alpha)
{
    if (!std::isfinite(a) || !(b > 0.0) || !std::isfinite(b) || !(lambda > 0.0)
        || !std::isfinite(lambda) || !(alpha > 0.0) || !(alpha <= 1.0)) {
        std::ostringstream os;
        os << "coag::GrowthLaw::addTransition: a finite rate factor, a positive diameter "
              "factor and mean free path and an accommodation coefficient in (0, 1] are "
              "needed, got a = "
           << a << ", b = " << b << ", lambda = " << lambda << ", alpha = " << alpha;
        throw std::invalid_argument(os.str());
    }
    if (a == 0.0) return;
    transitions_.push_back({a, b, lambda, alpha});
}

double GrowthLaw::rate(double m) const
{
    double r = 0.0;
    for (const Power& p : powers_) {
        r += p.q == 0.0 ? p.c : p.c * std::pow(m, p.q);
    }
    if (!transitions_.empty()) {
        const double m13 = std::cbrt(m);
        for (const Transition& t : transitions_) {
            const double d = t.b * m13;
            r += t.a * d * fuchsSutugin(2.0 * t.lambda / d, t.alpha);
        }
    }
    return r;
}

double GrowthLaw::yRate(double y) const
{
    // m = y^3: dy/dt = (dm/dt) / (3 y^2)
    return rate(y * y * y) / (3.0 * y * y);
}

GrowthLaw::Step GrowthLaw::advance(double m, double dt, double minMass) const
{
    if (!(m > 0.0) || !std::isfinite(m) || !(dt >= 0.0) || !std::isfinite(dt)
        || !(minMass >= 0.0)) {
        std::ostringstream os;
        os << "coag::GrowthLaw::advance: needs a finite mass > 0, a finite step >= 0 and a "
              "threshold >= 0, got "
           << m << ", " << dt << ", " << minMass;
        throw std::invalid_argument(os.str());
    }
    // A particle at or below the threshold already is gone at its own mass (an inflow or an
    // initial particle smaller than the minimum)
    if (!(m > minMass)) return {m, true};
    if (empty() || dt == 0.0) return {m, false};
    return closedForm() ? closed(m, dt, minMass) : adaptive(m, dt, minMass);
}

GrowthLaw::Step GrowthLaw::closed(double m, double dt, double minMass) const
{
    const double c = powers_.front().c;
    const double q = powers_.front().q;
    double end = 0.0;
    if (q == 1.0) {
        end = m * std::exp(c * dt);
    } else if (q == 2.0 / 3.0) {
        // The surface law: m^(1/3) linear in time (cube roots, not powers: faster, exact to
        // a rounding)
        const double z = std::cbrt(m) + c * dt / 3.0;
        if (!(z > std::cbrt(minMass))) return {minMass, true};
        end = z * z * z;
    } else if (q == 1.0 / 3.0) {
        // The diameter law: m^(2/3) linear in time
        const double r = std::cbrt(m);
        const double z = r * r + 2.0 * c * dt / 3.0;
        const double rMin = std::cbrt(minMass);
        if (!(z > rMin * rMin)) return {minMass, true};
        end = z * std::sqrt(z);
    } else {
        // m^p linear in time, p = 1 - q > 0; gone where it reaches minMass^p (or 0)
        const double p = 1.0 - q;
        const double z = (p == 1.0 ? m : std::pow(m, p)) + p * c * dt;
        const double zMin = minMass > 0.0 ? (p == 1.0 ? minMass : std::pow(minMass, p)) : 0.0;
        if (!(z > zMin)) return {minMass, true};
        end = p == 1.0 ? z : std::pow(z, 1.0 / p);
    }
    if (!(end > minMass)) return {minMass, true};
    if (!std::isfinite(end)) {
        std::ostringstream os;
        os << "coag::GrowthLaw: a particle of mass " << m << " grows past the largest number in "
           << dt << " (dm/dt = " << c << " m^" << q << ")";
        throw std::runtime_error(os.str());
    }
    return {end, false};
}

GrowthLaw::Step GrowthLaw::adaptive(double m, double dt, double minMass) const
{
    // Dormand & Prince (1980) 5(4), the fifth-order solution carried on, in y = m^(1/3)
    constexpr double a21 = 1.0 / 5;
    constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
    constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
    constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                     a54 = -212.0 / 729;
    constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                     a64 = 49.0 / 176, a65 = -5103.0 / 18656;
    constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192,
                     b5 = -2187.0 / 6784, b6 = 11.0 / 84;
    // Fifth minus fourth order weights: the local error estimate
    constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                     e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
    constexpr double tolerance = 1e-10;
    constexpr long maxSteps = 100000;

    const double yMin = std::cbrt(minMass);
    double y = std::cbrt(m);
    double t = 0.0;
    double h = dt;
    double k1 = yRate(y);
    // A stage whose y is not positive lies past the threshold (the rate is not defined there)
    auto past = [yMin](double v) { return !(v > yMin) || !(v > 0.0); };

    for (long step = 0; t < dt; ++step) {
        if (step == maxSteps) {
            std::ostringstream os;
            os << "coag::GrowthLaw: " << maxSteps << " adaptive steps did not reach the end of "
               << "a step of " << dt << " from mass " << m;
            throw std::runtime_error(os.str());
        }
        // What is left of the step is negligible
        if (dt - t <= 1e-12 * dt) break;
        const bool last = h >= dt - t;
        if (last) h = dt - t;

        double y2 = y + h * a21 * k1, k2 = 0, k3 = 0, k4 = 0, k5 = 0, k6 = 0, k7 = 0, y5 = 0;
        bool crossed = past(y2);
        if (!crossed) {
            k2 = yRate(y2);
            const double y3 = y + h * (a31 * k1 + a32 * k2);
            crossed = past(y3);
            if (!crossed) {
                k3 = yRate(y3);
                const double y4 = y + h * (a41 * k1 + a42 * k2 + a43 * k3);
                crossed = past(y4);
                if (!crossed) {
                    k4 = yRate(y4);
                    const double y5s = y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4);
                    crossed = past(y5s);
                    if (!crossed) {
                        k5 = yRate(y5s);
                        const double y6 =
                            y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5);
                        crossed = past(y6);
                        if (!crossed) {
                            k6 = yRate(y6);
                            y5 = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
                            crossed = past(y5);
                            if (!crossed) k7 = yRate(y5);
                        }
                    }
                }
            }
        }
        if (crossed) {
            // The threshold lies within this step, or the step is too long to tell: a
            // shorter one
            h *= 0.25;
        } else {
            const double error =
                std::abs(h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7));
            const double scale = tolerance * std::max(std::abs(y), std::abs(y5));
            if (error <= scale) {
                t = last ? dt : t + h;
                y = y5;
                k1 = k7;  // first same as last
            }
            // Not finite (an overflowing stage): shorter
            const double factor = !(error < HUGE_VAL) ? 0.2
                                  : error > 0.0       ? 0.9 * std::pow(scale / error, 0.2)
                                                      : 5.0;
            h *= std::min(5.0, std::max(0.2, factor));
        }
        // Steps of a negligible part of dt: the solution runs into a singularity of the rate
        // within a negligible time, zero mass (where a constant term's dy/dt ~ 1/y^2) when
        // it shrinks, infinity when it grows
        if (h <= 1e-12 * dt) {
            if (k1 < 0.0) return {minMass, true};
            std::ostringstream os;
            os << "coag::GrowthLaw: a particle of mass " << m << " grows without bound within "
               << "a step of " << dt;
            throw std::runtime_error(os.str());
        }
    }
    const double end = y * y * y;
    if (!(end > minMass)) return {minMass, true};
    if (!std::isfinite(end)) {
        std::ostringstream os;
        os << "coag::GrowthLaw: a particle of mass " << m << " grows past the largest number in "
           << dt;
        throw std::runtime_error(os.str());
    }
    return {end, false};
}

} // namespace coag
