// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/kernels/CoagulationKernel.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace coag {

double CoagulationKernel::majorant(const ParticleType& a, const ParticleType& b,
                                   int group) const
{
    const std::size_t nb = static_cast<std::size_t>(nBasis());
    double stackA[16], stackB[16];
    std::vector<double> heapA, heapB;
    double* pa = stackA;
    double* pb = stackB;
    if (nb > 16) {
        heapA.resize(nb);
        heapB.resize(nb);
        pa = heapA.data();
        pb = heapB.data();
    }
    basis(a, pa);
    basis(b, pb);
    double sum = 0.0;
    for (const MajorantTerm& t : majorantTerms()) {
        if (t.group == group) sum += t.coeff * pa[t.first] * pb[t.second];
    }
    return sum;
}

double CoagulationKernel::majorant(const ParticleType& a, const ParticleType& b) const
{
    double least = majorant(a, b, 0);
    for (int g = 1; g < nMajorantGroups(); ++g) least = std::min(least, majorant(a, b, g));
    return least;
}

int CoagulationKernel::nMajorantGroups() const
{
    int groups = 1;
    for (const MajorantTerm& t : majorantTerms()) groups = std::max(groups, t.group + 1);
    return groups;
}

ScaledKernel::ScaledKernel(const char* kernel, double K0, std::vector<MajorantTerm> unitTerms)
    : K0_(K0), terms_(std::move(unitTerms))
{
    if (!(K0 > 0.0) || !std::isfinite(K0)) {
        std::ostringstream os;
        os << "coag::" << kernel << "Kernel: K0 must be positive and finite, got " << K0;
        throw std::invalid_argument(os.str());
    }
    for (MajorantTerm& t : terms_) t.coeff *= K0_;
}

ConstantKernel::ConstantKernel(double K0) : ScaledKernel("Constant", K0, {{1.0, 0, 0}}) {}

AdditiveKernel::AdditiveKernel(double K0)
    : ScaledKernel("Additive", K0, {{1.0, 1, 0}, {1.0, 0, 1}})
{}

MultiplicativeKernel::MultiplicativeKernel(double K0)
    : ScaledKernel("Multiplicative", K0, {{1.0, 0, 0}})
{}

SaffmanTurnerKernel::SaffmanTurnerKernel(double K0)
    : ScaledKernel("SaffmanTurner", K0, {{1.0, 1, 0}, {3.0, 3, 2}, {3.0, 2, 3}, {1.0, 0, 1}})
{}

double SaffmanTurnerKernel::operator()(const ParticleType& a, const ParticleType& b) const
{
    const double s = std::cbrt(a.mass) + std::cbrt(b.mass);
    return K0_ * s * s * s;
}

void SaffmanTurnerKernel::basis(const ParticleType& z, double* phi) const
{
    const double c = std::cbrt(z.mass);
    phi[0] = 1.0;
    phi[1] = z.mass;
    phi[2] = c;
    phi[3] = c * c;
}

double saffmanTurnerK0(double epsilon, double nu, double V1)
{
    for (double v : {epsilon, nu, V1})
        if (!(v > 0.0) || !std::isfinite(v))
            throw std::invalid_argument(
                "coag::saffmanTurnerK0: epsilon, nu and V1 must be positive and finite");
    const double pi = 3.14159265358979323846;
    return std::sqrt(pi * pi * epsilon / (120.0 * nu)) * V1;   // (1.2), (5.2)
}

std::vector<std::string> kernelNames()
{
    return {"constant", "additive", "multiplicative", "saffmanTurner"};
}

std::unique_ptr<CoagulationKernel> makeKernel(const std::string& name, double K0)
{
    if (name == "constant") return std::make_unique<ConstantKernel>(K0);
    if (name == "additive") return std::make_unique<AdditiveKernel>(K0);
    if (name == "multiplicative") return std::make_unique<MultiplicativeKernel>(K0);
    if (name == "saffmanTurner") return std::make_unique<SaffmanTurnerKernel>(K0);
    std::ostringstream os;
    os << "coag::makeKernel: unknown kernel '" << name << "'; valid names are:";
    for (const std::string& n : kernelNames()) os << ' ' << n;
    throw std::invalid_argument(os.str());
}

} // namespace coag
