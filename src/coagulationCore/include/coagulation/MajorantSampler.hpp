// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_MAJORANTSAMPLER_HPP
#define COAGULATION_MAJORANTSAMPLER_HPP

#include "coagulation/CoagulationKernel.hpp"
#include "coagulation/Particle.hpp"
#include "coagulation/Rng.hpp"
#include "coagulation/SumTree.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace coag {

//- Pair proposals from a kernel's product-form majorant (CoagulationKernel.hpp)
//      Khat(z1,z2) = sum_t coeff_t phi_first(z1) phi_second(z2)  >=  K(z1,z2)
//  over the particles of one cell: the coagulation part of every cell algorithm.
//
//  The summed majorant rate over ordered pairs (j1, j2), j1 == j2 included, is
//      sum_t coeff_t S_first,t S_second,t,   S_first = sum_j phi_first(z_j),
//      S_second = sum_j phi_second(z_j) w_j   (weightedSecond: SWA's K w2 of eq 22)
//               = sum_j phi_second(z_j)       (otherwise: DSA, the common weight pulled out).
//  A proposal picks term t with probability coeff_t S_first S_second / sum, then
//  j1 ~ phi_first(z_j1) and j2 ~ phi_second(z_j2) (* w_j2). The caller rejects j1 == j2 and
//  accepts with probability K/Khat (majorant()), otherwise the jump is fictitious.
//
//  A "column" is one factor: phi_b or phi_b * w. Columns whose basis function is constant
//  (CoagulationKernel::constantBasis) and that carry no varying weight are drawn uniformly and
//  need no storage; the others live in a SumTree (fan-out 8, one flat array, exact sums).
//  Cost per event O(#terms + log N); no allocation per event.
//
//  Invariant: after build(), the tree's leaf j holds the columns of particle j for
//  j < n, zero above; every change of a particle goes through set() or removeBySwap().
class MajorantSampler {
public:
    explicit MajorantSampler(bool weightedSecond) : weightedSecond_(weightedSecond) {}

    //- Takes the kernel's majorant terms (O(#terms), no allocation once sized). The kernel
    //  must outlive the use until the next configure(). Throws std::invalid_argument,
    //  naming `who`, for a kernel without terms, an invalid term or a non-positive
    //  constant basis function.
    void configure(const CoagulationKernel& kernel, const std::string& who);

    const CoagulationKernel& kernel() const { return *kernel_; }

    //- All leaves from the particles, room for `capacity` (O(N)).
    void build(const std::vector<Particle>& particles, std::size_t capacity)
    {
        tree_.reset(nTreeColumns_, capacity > particles.size() ? capacity : particles.size());
        for (std::size_t j = 0; j < particles.size(); ++j) fillLeaf(particles[j], j);
        tree_.rebuild();
    }

    std::size_t capacity() const { return tree_.capacity(); }

    //- Particle j changed (or was appended at j = n - 1 after a capacity check).
    void set(const Particle& p, std::size_t j)
    {
        fillLeaf(p, j);
        updateLeaf(j);
    }

    //- Particle p appended at index j: grows the tree (doubling) when full.
    void append(const Particle& p, std::size_t j)
    {
        if (j >= tree_.capacity()) tree_.resizeCapacity(2 * tree_.capacity());
        set(p, j);
    }

    //- The particle at r removed by moving the last one (index last) into its slot.
    void removeBySwap(std::size_t r, std::size_t last)
    {
        if (r != last) {
            for (std::size_t c = 0; c < nTreeColumns_; ++c) tree_.set(r, c, tree_.value(last, c));
            updateLeaf(r);
        }
        for (std::size_t c = 0; c < nTreeColumns_; ++c) tree_.set(last, c, 0.0);
        updateLeaf(last);
    }

    //- sum_t coeff_t S_first,t S_second,t over n >= 2 particles (0 for fewer); keeps the
    //  per-term rates for propose().
    double rateSum(std::size_t n)
    {
        double sum = 0.0;
        if (n >= 2) {
            for (std::size_t k = 0; k < nTerms_; ++k) {
                termRate_[k] = termCoeff_[k] * columnTotal(columns_[termFirst_[k]], n)
                               * columnTotal(columns_[termSecond_[k]], n);
                sum += termRate_[k];
            }
        }
        return sum;
    }

    //- A proposal (j1, j2) for u uniform in [0, rateSum(n)); j1 == j2 is possible (and
    //  rejected by the caller). `particles` lets the tree prefetch the candidates' records.
#if defined(__GNUC__)
    __attribute__((always_inline))  // once per event, from one place: as fast as written inline
#endif
    void propose(double u, std::size_t n, Rng& rng, const Particle* particles, std::size_t& j1,
                 std::size_t& j2) const
    {
        std::size_t term = nTerms_ - 1;
        for (std::size_t k = 0; k + 1 < nTerms_; ++k) {
            if (u < termRate_[k]) {
                term = k;
                break;
            }
            u -= termRate_[k];
        }
        j1 = sampleColumn(columns_[termFirst_[term]], n, rng, particles);
#if defined(__GNUC__)
        __builtin_prefetch(&particles[j1 < n ? j1 : 0]);
#endif
        if (nTreeColumns_ > 0) tree_.prefetchPath(j1);
        j2 = sampleColumn(columns_[termSecond_[term]], n, rng, particles);
    }

    //- Khat(z1, z2), from the basis at the two types (the values the tree holds, without
    //  touching the tree's other columns).
    double majorant(const ParticleType& z1, const ParticleType& z2)
    {
        kernel_->basis(z1, phi_.data());
        kernel_->basis(z2, phi2_.data());
        double sum = 0.0;
        for (std::size_t k = 0; k < nTerms_; ++k) {
            sum += termCoeff_[k] * phi_[termFirstBasis_[k]] * phi2_[termSecondBasis_[k]];
        }
        return sum;
    }

    //- Bytes of the sum tree currently held
    std::size_t memoryBytes() const { return tree_.memoryBytes(); }

private:
    struct Column {
        int basis = 0;
        bool weighted = false;  // phi * w (SWA second factors)
        bool uniform = false;   // constant phi, no weight: uniform selection, no tree column
        double constant = 0.0;  // phi when uniform
        std::size_t tree = 0;   // tree column when not uniform
    };

    std::size_t columnFor(int b, bool weighted, const std::string& who);

    void fillLeaf(const Particle& p, std::size_t j)
    {
        if (nTreeColumns_ == 0) return;
        kernel_->basis(p.type, phi_.data());
        // Runs once per event: only the tree columns, in tree-column order
        for (std::size_t c = 0; c < nTreeColumns_; ++c) {
            const double v = phi_[treeBasis_[c]];
            tree_.set(j, c, treeWeighted_[c] ? v * p.weight : v);
        }
    }

    void updateLeaf(std::size_t j)
    {
        if (nTreeColumns_ > 0) tree_.update(j);
    }

    double columnTotal(const Column& col, std::size_t n) const
    {
        return col.uniform ? col.constant * static_cast<double>(n) : tree_.total(col.tree);
    }

    std::size_t sampleColumn(const Column& col, std::size_t n, Rng& rng,
                             const Particle* particles) const
    {
        if (col.uniform) return static_cast<std::size_t>(rng.uniformIndex(n));
        return tree_.sample(col.tree, rng.uniform() * tree_.total(col.tree), particles,
                            sizeof(Particle));
    }

    bool weightedSecond_;
    const CoagulationKernel* kernel_ = nullptr;
    std::vector<Column> columns_;
    std::size_t nTreeColumns_ = 0;
    std::vector<std::size_t> treeBasis_;  // per tree column: its basis function
    std::vector<char> treeWeighted_;      // per tree column: phi * w
    std::size_t nTerms_ = 0;
    std::vector<double> termCoeff_;
    std::vector<std::size_t> termFirst_;   // column of phi_first
    std::vector<std::size_t> termSecond_;  // column of phi_second (* w for SWA)
    std::vector<double> termRate_;
    std::vector<std::size_t> termFirstBasis_;
    std::vector<std::size_t> termSecondBasis_;
    std::vector<double> phi_;
    std::vector<double> phi2_;
    SumTree tree_;
};

} // namespace coag

#endif
