// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Kernels with several majorants (groups of terms): the sampler proposes from the group of
// the least summed rate when the cell step starts, and the jump processes stay exact when the
// choice changes from one step to the next.
#include "TestHelpers.hpp"

using namespace coagtest;

namespace {

//- K = K0, given with two majorants: group 0 the constant 3 K0, group 1 K0 (x + y)/2 (>= K0
//  for masses >= 1). From a start of monomers group 1 is the tighter one; once the mean mass
//  passes 3 (t > 4 / (K0 N0)) group 0 is.
class TwoMajorantsConstantKernel : public CoagulationKernel {
public:
    explicit TwoMajorantsConstantKernel(double K0)
        : K0_(K0), terms_{{3.0 * K0, 0, 0, 0}, {0.5 * K0, 1, 0, 1}, {0.5 * K0, 0, 1, 1}}
    {}
    std::string name() const override { return "twoMajorantsConstant"; }
    double operator()(const ParticleType&, const ParticleType&) const override { return K0_; }
    int nBasis() const override { return 2; }
    void basis(const ParticleType& z, double* phi) const override
    {
        phi[0] = 1.0;
        phi[1] = z.mass;
    }
    const std::vector<MajorantTerm>& majorantTerms() const override { return terms_; }
    bool constantBasis(int b) const override { return b == 0; }

private:
    double K0_;
    std::vector<MajorantTerm> terms_;
};

TEST(MajorantGroups, RateSumIsTheLeastGroupsSum)
{
    const TwoMajorantsConstantKernel kernel(1.0);
    EXPECT_EQ(kernel.nMajorantGroups(), 2);
    for (double mass : {1.0, 10.0}) {
        std::vector<Particle> P;
        for (int j = 0; j < 20; ++j) P.push_back(Particle{ParticleType{mass}, 1.0, j});
        MajorantSampler sampler(false);
        sampler.configure(kernel, "test");
        sampler.build(P, P.size());
        // group 0: 3 n^2; group 1: (1/2)(2 n sum m) = n sum m
        const double n = P.size();
        const double expected = std::min(3.0 * n * n, n * n * mass);
        EXPECT_NEAR(sampler.rateSum(P.size()), expected, 1e-12 * expected) << mass;
        for (const Particle& a : P) {
            EXPECT_NEAR(sampler.pairRate(a, P[0]), std::min(3.0, mass), 1e-12) << mass;
        }
    }
}

//- The constant-kernel solution, through both majorants in turn, for SWA, DSA1 and DSA2;
//  fewer fictitious jumps than with the constant majorant 3 K0 alone
class MajorantGroupsTest : public ::testing::TestWithParam<std::string> {};

TEST_P(MajorantGroupsTest, ConstantKernelThroughTwoMajorants)
{
    const double K0 = 1.0, N0 = 1.0;
    const TwoMajorantsConstantKernel kernel(K0);
    // cell steps of 0.5 (the group is chosen as each starts), as a solver's steps would be
    std::vector<double> times;
    for (int k = 1; k <= 20; ++k) times.push_back(0.5 * k);
    auto exact = [&](double t) { return exact::constantKernelMoments(K0, N0, t); };
    const auto res = runEnsemble(
        GetParam(), kernel, InceptionModel{}, NumberControl{},
        [&] { return monodisperse(1000, 1000 / N0); }, times, 300, 31);
    expectMomentsMatch(res, times, exact, 3, GetParam() + " two majorants");
    // With 3 K0 alone two of three proposals are fictitious
    const double fictitiousPerReal =
        double(res.steps.fictitious) / double(res.steps.coagulations);
    EXPECT_LT(fictitiousPerReal, 1.5) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Algorithms, MajorantGroupsTest, ::testing::Values("SWA", "DSA1", "DSA2"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(MajorantGroups, RefusesGroupsOutOfOrder)
{
    class Shuffled : public TwoMajorantsConstantKernel {
    public:
        Shuffled() : TwoMajorantsConstantKernel(1.0), t_{{1.0, 0, 0, 1}, {1.0, 0, 0, 0}} {}
        const std::vector<MajorantTerm>& majorantTerms() const override { return t_; }

    private:
        std::vector<MajorantTerm> t_;
    } shuffled;
    MajorantSampler sampler(false);
    EXPECT_THROW(sampler.configure(shuffled, "test"), std::invalid_argument);
}

} // namespace
