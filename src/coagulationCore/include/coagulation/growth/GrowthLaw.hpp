// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_GROWTHLAW_HPP
#define COAGULATION_GROWTHLAW_HPP

// The mass change of a particle by exchange with the gas (surface growth, condensation,
// oxidation, evaporation) in one cell over one step, the cell's conditions fixed:
//
//     dm/dt = sum_k c_k m^q_k                                  (power terms)
//           + sum_j a_j d F(Kn, alpha_j),  d = b_j m^(1/3)     (transition terms)
//
// with F the Fuchs-Sutugin correction of the continuum condensation rate (Seinfeld & Pandis,
// Atmospheric Chemistry and Physics, eq. 12.43), Kn = 2 lambda / d:
//
//     F(Kn, alpha) = (1 + Kn) / (1 + (4/(3 alpha) + 0.377) Kn + 4 Kn^2 / (3 alpha)).
//
// The power terms cover the laws that integrate in closed form: constant dm/dt (q = 0),
// dm/dt proportional to m (q = 1), to the surface m^(2/3) (surface reactions, free-molecular
// condensation: d(d)/dt constant) and to the diameter m^(1/3) (continuum condensation:
// d(d^2)/dt constant). A law of one power term (terms of equal q are summed) is advanced in
// closed form, exact to round-off:
//
//     q = 1:   m(t) = m0 exp(c t)
//     q < 1:   m(t)^(1-q) = m0^(1-q) + (1-q) c t.
//
// Any other law (several exponents, a transition term) is advanced by an adaptive
// Dormand-Prince 5(4) step in y = m^(1/3), relative tolerance 1e-10.
//
// A particle whose mass falls to minMass or below within the step (or, for minMass 0, to
// zero) leaves the population: advance returns its mass at that size (one at or below
// minMass at the start: its own mass). The solution of the
// one-dimensional autonomous equation is monotone in time, so a particle that comes back
// above the threshold later in the step does not exist.

#include <cstddef>
#include <vector>

namespace coag {

class GrowthLaw {
public:
    //- The outcome of a particle's step: its mass at the end, or, gone, at the threshold
    struct Step {
        double mass = 0.0;
        bool gone = false;
    };

    //- No term: dm/dt = 0
    void clear()
    {
        powers_.clear();
        transitions_.clear();
    }

    bool empty() const { return powers_.empty() && transitions_.empty(); }

    //- dm/dt += c m^q; c finite, q <= 1 (a larger exponent reaches infinity in finite time),
    //  else std::invalid_argument. A zero c adds nothing.
    void addPower(double c, double q);

    //- dm/dt += a d F(2 lambda / d, alpha), d = b m^(1/3): condensation (a > 0) or
    //  evaporation (a < 0) in the transition regime, a = 2 pi D dc / (mass unit), b the
    //  diameter of a unit mass, lambda the vapour's mean free path, alpha the accommodation
    //  coefficient. a finite, b, lambda, alpha finite and > 0 (alpha <= 1), else
    //  std::invalid_argument.
    void addTransition(double a, double b, double lambda, double alpha);

    //- dm/dt at mass m > 0
    double rate(double m) const;

    //- Whether the law is one power term, advanced in closed form
    bool closedForm() const { return transitions_.empty() && powers_.size() == 1; }

    //- The particle of mass m > 0 after dt >= 0, with minMass >= 0 its threshold
    Step advance(double m, double dt, double minMass) const;

private:
    struct Power {
        double c;
        double q;
    };
    struct Transition {
        double a;
        double b;
        double lambda;
        double alpha;
    };

    Step closed(double m, double dt, double minMass) const;
    Step adaptive(double m, double dt, double minMass) const;

    //- dy/dt for y = m^(1/3)
    double yRate(double y) const;

    std::vector<Power> powers_;
    std::vector<Transition> transitions_;
};

//- The Fuchs-Sutugin factor F(Kn, alpha) above
double fuchsSutugin(double Kn, double alpha);

} // namespace coag

#endif
