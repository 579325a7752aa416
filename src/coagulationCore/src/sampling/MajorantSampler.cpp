// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/sampling/MajorantSampler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace coag {

std::size_t MajorantSampler::columnFor(int b, bool weighted, const std::string& who)
{
    for (std::size_t i = 0; i < nColumns_; ++i) {
        if (columns_[i].basis == b && columns_[i].weighted == weighted) return i;
    }
    Column col;
    col.basis = b;
    col.weighted = weighted;
    col.uniform = !weighted && kernel_->constantBasis(b);
    col.constant = constantPhi_[static_cast<std::size_t>(b)];
    if (col.uniform && !(col.constant > 0.0 && std::isfinite(col.constant))) {
        throw std::invalid_argument(who + ": kernel '" + kernel_->name()
                                    + "' declares a constant basis function that is not "
                                      "positive");
    }
    if (!col.uniform) {
        if (nTreeColumns_ == QuantizedSumTree::maxColumns) {
            throw std::invalid_argument(who + ": kernel '" + kernel_->name()
                                        + "' needs more than "
                                        + std::to_string(QuantizedSumTree::maxColumns)
                                        + " sampler columns");
        }
        col.tree = nTreeColumns_++;
        treeBasis_[col.tree] = static_cast<std::size_t>(b);
        treeWeighted_[col.tree] = weighted;
    }
    columns_[nColumns_] = col;  // at most 2 nBasis <= 2 maxBasis columns
    return nColumns_++;
}

void MajorantSampler::configure(const CoagulationKernel& kernel, const std::string& who)
{
    kernel_ = &kernel;
    const int nb = kernel.nBasis();
    const std::vector<MajorantTerm>& terms = kernel.majorantTerms();
    if (nb <= 0) {
        throw std::invalid_argument(who + ": kernel '" + kernel.name() + "' has no basis function");
    }
    if (static_cast<std::size_t>(nb) > maxBasis) {
        throw std::invalid_argument(who + ": kernel '" + kernel.name() + "' has "
                                    + std::to_string(nb) + " basis functions, at most "
                                    + std::to_string(maxBasis));
    }
    std::fill_n(phi_, maxBasis, 0.0);
    std::fill_n(phi2_, maxBasis, 0.0);
    std::fill_n(constantPhi_, maxBasis, 0.0);
    kernel.basis(ParticleType{}, constantPhi_);

    // The groups in order, each with terms: group g's are [groupBegin_[g], groupBegin_[g + 1])
    nGroups_ = 1;
    groupBegin_[0] = 0;
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const int g = terms[k].group;
        const int previous = k > 0 ? terms[k - 1].group : 0;
        if (g != previous && g != previous + 1) {
            throw std::invalid_argument(who + ": kernel '" + kernel.name()
                                        + "' lists its majorant groups out of order (0, 1, ...)");
        }
        if (g == previous + 1) {
            if (static_cast<std::size_t>(g) >= maxGroups) {
                throw std::invalid_argument(who + ": kernel '" + kernel.name() + "' has more than "
                                            + std::to_string(maxGroups) + " majorant groups");
            }
            groupBegin_[g] = k;
            nGroups_ = static_cast<std::size_t>(g) + 1;
        }
    }
    groupBegin_[nGroups_] = terms.size();
    for (std::size_t g = 0; g < nGroups_; ++g) {
        if (groupBegin_[g + 1] - groupBegin_[g] > maxTerms) {
            throw std::invalid_argument(who + ": kernel '" + kernel.name() + "' has "
                                        + std::to_string(groupBegin_[g + 1] - groupBegin_[g])
                                        + " terms in a majorant, at most "
                                        + std::to_string(maxTerms));
        }
    }

    std::size_t k = 0;
    for (const MajorantTerm& t : terms) {
        if (t.first < 0 || t.first >= nb || t.second < 0 || t.second >= nb || !(t.coeff > 0.0)
            || !std::isfinite(t.coeff)) {
            throw std::invalid_argument(who + ": kernel '" + kernel.name()
                                        + "' has an invalid majorant term (coeff must be > 0, "
                                          "basis indices in [0, nBasis))");
        }
        allCoeff_[k] = t.coeff;
        allFirst_[k] = t.first;
        allSecond_[k] = t.second;
        ++k;
    }
    // Every group's columns checked now, not at the build that would first choose it
    for (std::size_t g = nGroups_; g-- > 0;) useGroup(g, who);
    std::fill_n(leaf_, QuantizedSumTree::maxColumns, 0.0);
    std::fill_n(columnTotals_, QuantizedSumTree::maxColumns, 0.0);
}

void MajorantSampler::useGroup(std::size_t g, const std::string& who)
{
    activeGroup_ = g;
    nColumns_ = 0;
    nTreeColumns_ = 0;
    nTerms_ = groupBegin_[g + 1] - groupBegin_[g];
    for (std::size_t k = 0; k < nTerms_; ++k) {
        const std::size_t t = groupBegin_[g] + k;
        termCoeff_[k] = allCoeff_[t];
        termFirst_[k] = columnFor(allFirst_[t], false, who);
        termSecond_[k] = columnFor(allSecond_[t], weightedSecond_, who);
    }
    std::fill_n(termRate_, maxTerms, 0.0);
    // No term (K = 0): rateSum() is zero and no pair is ever proposed
    lastTerm_ = nTerms_ > 0 ? nTerms_ - 1 : 0;
}

void MajorantSampler::chooseGroup(const Particle* particles, std::size_t n)
{
    // sum_j phi_b(z_j) and sum_j phi_b(z_j) w_j for every basis function over at most
    // chooseSample particles evenly spaced in the store: every group is a majorant, so any
    // choice is exact, and a sample of the population chooses as well as all of it at a
    // bounded cost a step
    double first[maxBasis] = {}, second[maxBasis] = {};
    const std::size_t nb = static_cast<std::size_t>(kernel_->nBasis());
    const std::size_t stride = (n + chooseSample - 1) / chooseSample;
    for (std::size_t j = 0; j < n; j += (stride > 0 ? stride : 1)) {
        kernel_->basis(particles[j].type, phi2_);
        const double w = weightedSecond_ ? particles[j].weight : 1.0;
        for (std::size_t b = 0; b < nb; ++b) {
            first[b] += phi2_[b];
            second[b] += phi2_[b] * w;
        }
    }
    double least = 0.0;
    std::size_t best = 0;
    for (std::size_t g = 0; g < nGroups_; ++g) {
        double sum = 0.0;
        for (std::size_t t = groupBegin_[g]; t < groupBegin_[g + 1]; ++t) {
            sum += allCoeff_[t] * first[allFirst_[t]] * second[allSecond_[t]];
        }
        if (g == 0 || sum < least) {
            least = sum;
            best = g;
        }
    }
    // The columns were checked by configure(): no throw here
    if (best != activeGroup_) useGroup(best, std::string());
}

} // namespace coag
