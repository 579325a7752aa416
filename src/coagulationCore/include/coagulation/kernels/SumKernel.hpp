// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_SUMKERNEL_HPP
#define COAGULATION_SUMKERNEL_HPP

#include "coagulation/kernels/CoagulationKernel.hpp"

#include <memory>
#include <string>
#include <vector>

namespace coag {

//- The sum of independent coagulation mechanisms, K = sum_p K_p (e.g. Brownian motion and
//  differential settling: their rates add when the mechanisms are independent, as Seinfeld &
//  Pandis, Atmospheric Chemistry and Physics, appendix 13.A, add them).
//  The parts are shared (a part may be held elsewhere, e.g. by a per-cell model), read only.
//
//  The majorant is the sum of the parts' majorants: the basis functions are the parts' ones
//  concatenated (part p's basis b is b + offset_p), their terms shifted accordingly.
//  Groups: a part with several majorant groups (each >= K_p) gives several candidate sums.
//  The sum's groups are all the combinations (g_1, ..., g_P) of one group per part, numbered
//  in mixed radix with the first part varying slowest; the combination's terms are the parts'
//  terms of their groups. Each combination is sum_p Khat_p,g_p >= sum_p K_p = K, so each is a
//  complete majorant, and the least summed rate over the population, the sampler's choice, is
//  the combination of each part's least group: the sum is as tight as its parts at every
//  time. The cost is the number of terms: sum over combinations of their terms, so the group
//  counts multiply (two parts of two groups give four groups). The sampler's limits
//  (MajorantSampler::maxBasis, maxTerms, its groups and tree columns) are checked when an
//  algorithm takes the kernel, not here: the grid checks of a sum need no sampler.
class SumKernel : public CoagulationKernel {
public:
    using Part = std::shared_ptr<const CoagulationKernel>;

    //- Throws std::invalid_argument for no part or a null part.
    explicit SumKernel(std::vector<Part> parts);

    std::string name() const override { return "sum"; }
    double operator()(const ParticleType& a, const ParticleType& b) const override;
    int nBasis() const override { return nBasis_; }
    void basis(const ParticleType& z, double* phi) const override;
    const std::vector<MajorantTerm>& majorantTerms() const override { return terms_; }
    bool constantBasis(int b) const override;

    const std::vector<Part>& parts() const { return parts_; }

    //- Part p's first basis function in this kernel's basis
    int offset(std::size_t p) const { return offsets_[p]; }

private:
    std::vector<Part> parts_;
    std::vector<int> offsets_;
    int nBasis_ = 0;
    std::vector<MajorantTerm> terms_;
};

} // namespace coag

#endif
