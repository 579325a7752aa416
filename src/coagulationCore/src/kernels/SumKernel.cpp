// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/kernels/SumKernel.hpp"

#include <stdexcept>
#include <utility>

namespace coag {

SumKernel::SumKernel(std::vector<Part> parts) : parts_(std::move(parts))
{
    if (parts_.empty()) throw std::invalid_argument("coag::SumKernel: no part");
    std::vector<int> groups;
    for (const Part& p : parts_) {
        if (!p) throw std::invalid_argument("coag::SumKernel: a null part");
        offsets_.push_back(nBasis_);
        nBasis_ += p->nBasis();
        groups.push_back(p->nMajorantGroups());
    }

    // The combinations (g_1, ..., g_P) in mixed radix, the last part varying fastest
    std::size_t nCombinations = 1;
    for (int g : groups) nCombinations *= static_cast<std::size_t>(g);
    std::vector<int> combination(parts_.size(), 0);
    for (std::size_t c = 0; c < nCombinations; ++c) {
        std::size_t rest = c;
        for (std::size_t p = parts_.size(); p-- > 0;) {
            combination[p] = static_cast<int>(rest % static_cast<std::size_t>(groups[p]));
            rest /= static_cast<std::size_t>(groups[p]);
        }
        for (std::size_t p = 0; p < parts_.size(); ++p) {
            for (MajorantTerm t : parts_[p]->majorantTerms()) {
                if (t.group != combination[p]) continue;
                t.first += offsets_[p];
                t.second += offsets_[p];
                t.group = static_cast<int>(c);
                terms_.push_back(t);
            }
        }
    }
}

double SumKernel::operator()(const ParticleType& a, const ParticleType& b) const
{
    double k = 0.0;
    for (const Part& p : parts_) k += (*p)(a, b);
    return k;
}

void SumKernel::basis(const ParticleType& z, double* phi) const
{
    for (std::size_t p = 0; p < parts_.size(); ++p) parts_[p]->basis(z, phi + offsets_[p]);
}

bool SumKernel::constantBasis(int b) const
{
    std::size_t p = parts_.size() - 1;
    while (p > 0 && b < offsets_[p]) --p;
    return parts_[p]->constantBasis(b - offsets_[p]);
}

} // namespace coag
