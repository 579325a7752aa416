// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_COAGULATIONKERNEL_HPP
#define COAGULATION_COAGULATIONKERNEL_HPP

#include "coagulation/population/ParticleType.hpp"

#include <memory>
#include <string>
#include <vector>

namespace coag {

//- One term of a product-form majorant: coeff * phi_first(z1) * phi_second(z2), in the
//  majorant `group` (0 unless the kernel gives several).
struct MajorantTerm {
    double coeff;
    int first;
    int second;
    int group = 0;
};

//- Symmetric coagulation kernel K(z1,z2) with a majorant in product-sum form
//      Khat(z1,z2) = sum_t coeff_t phi_{first_t}(z1) phi_{second_t}(z2) >= K(z1,z2),
//  with basis functions phi_b >= 0 and coeff_t > 0. The particle algorithms select pairs
//  from Khat and accept with probability K/Khat (fictitious jumps otherwise). A majorant
//  without terms is K = 0 (NoCoagulationKernel).
//  A kernel may give several majorants, each a group of terms (groups 0, 1, ..., their terms
//  listed in that order), each >= K on its own: the sampler proposes from the one whose sum
//  over the population is the least at every build of the sampler's tree (when the cell step
//  starts, and after a halving or doubling of the population; as MOpS chooses between its
//  free-molecular and slip-flow majorants), so the fictitious jumps are those of the tighter
//  one, and the sampler's tree holds that group's columns only.
class CoagulationKernel {
public:
    virtual ~CoagulationKernel() = default;
    virtual std::string name() const = 0;
    virtual double operator()(const ParticleType& a, const ParticleType& b) const = 0;
    virtual int nBasis() const = 0;
    //- phi[0..nBasis()) at z; all values must be >= 0.
    virtual void basis(const ParticleType& z, double* phi) const = 0;
    virtual const std::vector<MajorantTerm>& majorantTerms() const = 0;
    //- True if phi_b does not depend on z (lets the algorithms pick such a factor uniformly
    //  instead of through the sum tree). Default: false.
    virtual bool constantBasis(int b) const { (void)b; return false; }

    //- The majorant of one group at (a, b) (non-virtual helper)
    double majorant(const ParticleType& a, const ParticleType& b, int group) const;

    //- The least of the groups' majorants at (a, b): the tightest bound K <= Khat there
    double majorant(const ParticleType& a, const ParticleType& b) const;

    //- The number of majorant groups (1 + the largest group of a term; 1 without terms)
    int nMajorantGroups() const;
};

//- The kernels below: K0 times a fixed shape, whose product-sum majorant is the shape's
//  own terms scaled by K0. Holds and checks K0 (> 0, finite) and the scaled terms.
class ScaledKernel : public CoagulationKernel {
public:
    const std::vector<MajorantTerm>& majorantTerms() const override { return terms_; }
    double K0() const { return K0_; }

protected:
    //- unitTerms: the majorant terms for K0 = 1
    ScaledKernel(const char* kernel, double K0, std::vector<MajorantTerm> unitTerms);

    double K0_;

private:
    std::vector<MajorantTerm> terms_;
};

//- K = K0.
class ConstantKernel : public ScaledKernel {
public:
    explicit ConstantKernel(double K0);
    std::string name() const override { return "constant"; }
    double operator()(const ParticleType&, const ParticleType&) const override { return K0_; }
    int nBasis() const override { return 1; }
    void basis(const ParticleType&, double* phi) const override { phi[0] = 1.0; }
    bool constantBasis(int b) const override { return b == 0; }
};

//- K = K0 (x + y), x, y the masses (Golovin). Basis {1, x}.
class AdditiveKernel : public ScaledKernel {
public:
    explicit AdditiveKernel(double K0);
    std::string name() const override { return "additive"; }
    double operator()(const ParticleType& a, const ParticleType& b) const override
    {
        return K0_ * (a.mass + b.mass);
    }
    int nBasis() const override { return 2; }
    void basis(const ParticleType& z, double* phi) const override
    {
        phi[0] = 1.0;
        phi[1] = z.mass;
    }
    bool constantBasis(int b) const override { return b == 0; }
};

//- K = K0 x y. Basis {x}.
class MultiplicativeKernel : public ScaledKernel {
public:
    explicit MultiplicativeKernel(double K0);
    std::string name() const override { return "multiplicative"; }
    double operator()(const ParticleType& a, const ParticleType& b) const override
    {
        return K0_ * a.mass * b.mass;
    }
    int nBasis() const override { return 1; }
    void basis(const ParticleType& z, double* phi) const override { phi[0] = z.mass; }
};

//- Saffman–Turner turbulent kernel K = K0 (x^{1/3} + y^{1/3})^3 (Kolodko–Sabelfeld–Wagner
//  eq 1.2 with K0 = (pi^2 eps / 120 nu)^{1/2} V1; K0 = 1/8 gives K11 = 1).
//  Exact product-sum form x + 3 x^{2/3} y^{1/3} + 3 x^{1/3} y^{2/3} + y with basis
//  {1, x, x^{1/3}, x^{2/3}}.
class SaffmanTurnerKernel : public ScaledKernel {
public:
    explicit SaffmanTurnerKernel(double K0);
    std::string name() const override { return "saffmanTurner"; }
    double operator()(const ParticleType& a, const ParticleType& b) const override;
    int nBasis() const override { return 4; }
    void basis(const ParticleType& z, double* phi) const override;
    bool constantBasis(int b) const override { return b == 0; }
};

//- K = 0: no coagulation (inception, transport and growth alone). Its majorant has no
//  term, so the algorithms' pair rate is zero and only inception makes events.
class NoCoagulationKernel : public CoagulationKernel {
public:
    std::string name() const override { return "none"; }
    double operator()(const ParticleType&, const ParticleType&) const override { return 0.0; }
    int nBasis() const override { return 1; }
    void basis(const ParticleType&, double* phi) const override { phi[0] = 1.0; }
    const std::vector<MajorantTerm>& majorantTerms() const override { return noTerms_; }
    bool constantBasis(int) const override { return true; }

private:
    std::vector<MajorantTerm> noTerms_;
};

//- K0 of the Saffman–Turner kernel (1.2)/(5.2) from the mean dissipation rate epsilon-bar,
//  the kinematic viscosity nu and the monomer volume V1: K0 = (pi^2 epsilon / (120 nu))^{1/2} V1
//  (so K11 = 8 K0). Throws std::invalid_argument unless all three are positive and finite.
double saffmanTurnerK0(double epsilon, double nu, double V1);

//- "constant", "additive", "multiplicative", "saffmanTurner"; unknown name or K0 <= 0
//  throws std::invalid_argument.
std::unique_ptr<CoagulationKernel> makeKernel(const std::string& name, double K0);

//- The names makeKernel accepts.
std::vector<std::string> kernelNames();

} // namespace coag

#endif
