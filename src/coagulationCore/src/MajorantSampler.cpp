// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/MajorantSampler.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace coag {

std::size_t MajorantSampler::columnFor(int b, bool weighted, const std::string& who)
{
    for (std::size_t i = 0; i < columns_.size(); ++i) {
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
        col.tree = nTreeColumns_++;
        treeBasis_.push_back(static_cast<std::size_t>(b));
        treeWeighted_.push_back(weighted);
    }
    columns_.push_back(col);
    return columns_.size() - 1;
}

void MajorantSampler::configure(const CoagulationKernel& kernel, const std::string& who)
{
    kernel_ = &kernel;
    const int nb = kernel.nBasis();
    const std::vector<MajorantTerm>& terms = kernel.majorantTerms();
    if (nb <= 0 || terms.empty()) {
        throw std::invalid_argument(who + ": kernel '" + kernel.name() + "' has no majorant terms");
    }
    phi_.assign(static_cast<std::size_t>(nb), 0.0);
    phi2_.assign(static_cast<std::size_t>(nb), 0.0);
    kernel.basis(ParticleType{}, phi_.data());

    columns_.clear();
    nTreeColumns_ = 0;
    treeBasis_.clear();
    treeWeighted_.clear();
    termCoeff_.clear();
    termFirst_.clear();
    termSecond_.clear();
    for (const MajorantTerm& t : terms) {
        if (t.first < 0 || t.first >= nb || t.second < 0 || t.second >= nb || !(t.coeff > 0.0)
            || !std::isfinite(t.coeff)) {
            throw std::invalid_argument(who + ": kernel '" + kernel.name()
                                        + "' has an invalid majorant term (coeff must be > 0, "
                                          "basis indices in [0, nBasis))");
        }
        termCoeff_.push_back(t.coeff);
        termFirst_.push_back(columnFor(t.first, false, who));
        termSecond_.push_back(columnFor(t.second, weightedSecond_, who));
    }
    if (nTreeColumns_ > QuantizedSumTree::maxColumns) {
        throw std::invalid_argument(who + ": kernel '" + kernel.name() + "' needs "
                                    + std::to_string(nTreeColumns_)
                                    + " sampler columns, at most "
                                    + std::to_string(QuantizedSumTree::maxColumns));
    }
    nTerms_ = termCoeff_.size();
    termRate_.assign(nTerms_, 0.0);
    lastTerm_ = nTerms_ - 1;
    leaf_.assign(nTreeColumns_, 0.0);
    columnTotals_.assign(nTreeColumns_, 0.0);
    binned_ = false;
}

} // namespace coag
