// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The stochastic algorithms with the Brownian kernels against the deterministic reference:
// from a monodisperse start every mass is a multiple of the first one, so the discrete
// Smoluchowski equation (DiscreteSmoluchowski, Dormand–Prince, truncated far in the tail) is
// the exact reference.
#include "TestHelpers.hpp"

#include <cmath>

using namespace coagtest;

namespace {

//- A kernel in units of a monomer of mass m0 and of K(m0, m0): masses 1, 2, ... stand for
//  m0, 2 m0, ...; the majorant is the inner kernel's, scaled alike
class InMonomers : public CoagulationKernel {
public:
    InMonomers(const CoagulationKernel& inner, double m0)
        : inner_(inner), m0_(m0), scale_(1.0 / inner(ParticleType{m0}, ParticleType{m0})),
          terms_(inner.majorantTerms())
    {
        for (MajorantTerm& t : terms_) t.coeff *= scale_;
    }
    std::string name() const override { return inner_.name() + " in monomers"; }
    double operator()(const ParticleType& a, const ParticleType& b) const override
    {
        return scale_ * inner_(ParticleType{a.mass * m0_}, ParticleType{b.mass * m0_});
    }
    int nBasis() const override { return inner_.nBasis(); }
    void basis(const ParticleType& z, double* phi) const override
    {
        inner_.basis(ParticleType{z.mass * m0_}, phi);
    }
    const std::vector<MajorantTerm>& majorantTerms() const override { return terms_; }
    bool constantBasis(int b) const override { return inner_.constantBasis(b); }

private:
    const CoagulationKernel& inner_;
    double m0_, scale_;
    std::vector<MajorantTerm> terms_;
};

std::array<double, 4> discreteMoments(const Eigen::VectorXd& n)
{
    std::array<double, 4> m{0, 0, 0, 0};
    for (Eigen::Index l = 0; l < n.size(); ++l) {
        double p = 1.0;
        for (int k = 0; k < 4; ++k) {
            m[k] += p * n[l];
            p *= static_cast<double>(l + 1);
        }
    }
    return m;
}

//- Closed cell of 10 nm spheres (1800 kg/m3) in air at 1500 K and 1 bar, N0 = 1 in these
//  units (time in 1 / (K(m0, m0) N0)): SWA, DSA1 and DSA2 against the discrete reference at
//  0.2, 2 and 20 (up to ten coagulation times 2 / (K N0)), for the free-molecular,
//  continuum and transition kernels. The reference's truncation (L = 400 and 800) changes
//  its moments by less than 1e-6.
class BrownianReferenceTest : public ::testing::TestWithParam<std::string> {};

TEST_P(BrownianReferenceTest, ClosedCellAgainstTheDiscreteReference)
{
    GasState gas;
    gas.T = 1500.0;
    gas.p = 1e5;
    gas.mu = sutherlandViscosity(gas.T);
    const ParticleMaterial material{1800.0};
    const double m0 = material.mass(10e-9);
    const std::vector<double> times{0.2, 2.0, 20.0};
    for (BrownianRegime regime : {BrownianRegime::freeMolecular, BrownianRegime::continuum,
                                  BrownianRegime::transition}) {
        const BrownianKernel brownian(regime, gas, material);
        const InMonomers kernel(brownian, m0);

        std::vector<std::array<double, 4>> reference[2];
        for (int level = 0; level < 2; ++level) {
            const std::size_t L = 400u << level;
            DiscreteSmoluchowski ode(kernel, L);
            Eigen::VectorXd n = Eigen::VectorXd::Zero(Eigen::Index(L));
            n[0] = 1.0;
            double t = 0.0;
            for (double ti : times) {
                n = ode.integrate(n, t, ti);
                t = ti;
                reference[level].push_back(discreteMoments(n));
            }
        }
        for (std::size_t i = 0; i < times.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(reference[0][i][k] / reference[1][i][k], 1.0, 1e-6)
                    << brownianRegimeName(regime) << " M" << k;
            }
        }

        const auto res = runEnsemble(GetParam(), kernel, InceptionModel{}, NumberControl{},
                                     [] { return monodisperse(1000, 1000.0); }, times, 60, 41);
        auto refAt = [&](double t) {
            std::size_t i = 0;
            while (i + 1 < times.size() && times[i] != t) ++i;
            return reference[1][i];
        };
        expectMomentsMatch(res, times, refAt, 3,
                           GetParam() + " Brownian " + brownianRegimeName(regime));
    }
}

INSTANTIATE_TEST_SUITE_P(Algorithms, BrownianReferenceTest,
                         ::testing::Values("SWA", "DSA1", "DSA2"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

} // namespace
