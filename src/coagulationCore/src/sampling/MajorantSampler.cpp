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
    col.constant = phi_[static_cast<std::size_t>(b)];
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
    if (static_cast<std::size_t>(nb) > maxBasis || terms.size() > maxTerms) {
        throw std::invalid_argument(who + ": kernel '" + kernel.name() + "' has "
                                    + std::to_string(nb) + " basis functions and "
                                    + std::to_string(terms.size())
                                    + " majorant terms, at most " + std::to_string(maxBasis)
                                    + " and " + std::to_string(maxTerms));
    }
    std::fill_n(phi_, maxBasis, 0.0);
    std::fill_n(phi2_, maxBasis, 0.0);
    kernel.basis(ParticleType{}, phi_);

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

    nColumns_ = 0;
    nTreeColumns_ = 0;
    std::size_t k = 0;
    for (const MajorantTerm& t : terms) {
        if (t.first < 0 || t.first >= nb || t.second < 0 || t.second >= nb || !(t.coeff > 0.0)
            || !std::isfinite(t.coeff)) {
            throw std::invalid_argument(who + ": kernel '" + kernel.name()
                                        + "' has an invalid majorant term (coeff must be > 0, "
                                          "basis indices in [0, nBasis))");
        }
        allCoeff_[k] = t.coeff;
        allFirst_[k] = columnFor(t.first, false, who);
        allSecond_[k] = columnFor(t.second, weightedSecond_, who);
        ++k;
    }
    activate(0);
    std::fill_n(termRate_, maxTerms, 0.0);
    // No term (K = 0): rateSum() is zero and no pair is ever proposed
    lastTerm_ = nTerms_ > 0 ? nTerms_ - 1 : 0;
    std::fill_n(leaf_, QuantizedSumTree::maxColumns, 0.0);
    std::fill_n(columnTotals_, QuantizedSumTree::maxColumns, 0.0);
}

void MajorantSampler::activate(std::size_t g)
{
    activeGroup_ = g;
    nTerms_ = groupBegin_[g + 1] - groupBegin_[g];
    std::copy_n(allCoeff_ + groupBegin_[g], nTerms_, termCoeff_);
    std::copy_n(allFirst_ + groupBegin_[g], nTerms_, termFirst_);
    std::copy_n(allSecond_ + groupBegin_[g], nTerms_, termSecond_);
}

double MajorantSampler::leastGroupRateSum(std::size_t n)
{
    double least = 0.0;
    std::size_t best = 0;
    for (std::size_t g = 0; g < nGroups_; ++g) {
        double sum = 0.0;
        for (std::size_t k = groupBegin_[g]; k < groupBegin_[g + 1]; ++k) {
            allRate_[k] = allCoeff_[k] * columnTotal(columns_[allFirst_[k]], n)
                          * columnTotal(columns_[allSecond_[k]], n);
            sum += allRate_[k];
        }
        if (g == 0 || sum < least) {
            least = sum;
            best = g;
        }
    }
    if (best != activeGroup_) activate(best);
    lastTerm_ = 0;
    for (std::size_t k = 0; k < nTerms_; ++k) {
        termRate_[k] = allRate_[groupBegin_[best] + k];
        if (termRate_[k] > 0.0) lastTerm_ = k;
    }
    return least;
}

} // namespace coag
