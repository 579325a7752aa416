// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_MAJORANTSAMPLER_HPP
#define COAGULATION_MAJORANTSAMPLER_HPP

#include "coagulation/kernels/CoagulationKernel.hpp"
#include "coagulation/population/Particle.hpp"
#include "coagulation/random/Rng.hpp"
#include "coagulation/sampling/QuantizedSumTree.hpp"

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
//  accepts with probability targetRate / pairRate (K (* w2) over the pair's proposal rate),
//  otherwise the jump is fictitious. In the tree the columns hold integer majorants of the
//  values (QuantizedSumTree: Q = ceil(v / 2^e) 2^e, above v by less than 2^-33 of the
//  column's largest value up to 2^20 leaves), so the sums above are over Q and pairRate() is
//  computed from the Q's: a thinning of a majorant whose jump process is the exact one
//  (Gillespie with fictitious jumps).
//
//  A "column" is one factor: phi_b or phi_b * w. Columns whose basis function is constant
//  (CoagulationKernel::constantBasis) and that carry no varying weight are drawn uniformly and
//  need no storage; the others live in a QuantizedSumTree (fan-out 8, one flat array, exact
//  integer sums updated by one add per level): cost per event O(#terms + log N). When both
//  factors of a term are tree columns the two walks go down together
//  (QuantizedSumTree::samplePair), so that their cache misses overlap; the same random numbers
//  and leaves as two walks one after the other.
//  No allocation per event (append() doubles the capacity when full, as the tree does).
//
//  Invariant: after build(), leaf j of the store holds the columns of particle j for
//  j < n (the tree: zero above); every change of a particle goes through set(), append() or
//  removeBySwap().
class MajorantSampler {
public:
    //- The most basis functions and majorant terms of a kernel that configure() takes
    static constexpr std::size_t maxBasis = 16;
    static constexpr std::size_t maxTerms = 16;  // a majorant group's terms
    static constexpr std::size_t maxGroups = 4;

    explicit MajorantSampler(bool weightedSecond) : weightedSecond_(weightedSecond) {}

    //- Takes the kernel's majorant terms (O(#terms), no allocation once sized). The kernel
    //  must outlive the use until the next configure(). Throws std::invalid_argument,
    //  naming `who`, for a kernel without terms, an invalid term or a non-positive
    //  constant basis function.
    void configure(const CoagulationKernel& kernel, const std::string& who);

    const CoagulationKernel& kernel() const { return *kernel_; }

    //- All leaves from the particles, room for `capacity` (O(N)). A kernel of several
    //  majorant groups first has the group of the least summed majorant over the particles
    //  chosen: its columns alone are the tree's until the next build.
    template <class Allocator>
    void build(const std::vector<Particle, Allocator>& particles, std::size_t capacity)
    {
        build(particles.data(), particles.size(), capacity);
    }
    //- build() for the n particles at `particles`
    void build(const Particle* particles, std::size_t n, std::size_t capacity)
    {
        if (capacity < n) capacity = n;
        ahead_.valid = false;
        partial_.valid = false;
        if (nGroups_ > 1) chooseGroup(particles, n);
        if (nTreeColumns_ == 0) {
            tree_.reset(0, capacity);
            return;
        }
        tree_.build(nTreeColumns_, capacity, n, [this, particles](std::size_t j, double* v) {
            basisColumns(particles[j], v);
        });
    }

    std::size_t capacity() const { return tree_.capacity(); }

    //- Particle j < n changed.
    void set(const Particle& p, std::size_t j)
    {
        if (nTreeColumns_ == 0) return;
        basisColumns(p);
        tree_.assign(j, leaf_);
    }

    //- Particle p appended at index j = n: grows the store (doubling) when full.
    void append(const Particle& p, std::size_t j)
    {
        if (j >= tree_.capacity()) tree_.resizeCapacity(2 * tree_.capacity());
        set(p, j);
    }

    //- The particle at r removed by moving the last one (index last = n - 1) into its slot.
    void removeBySwap(std::size_t r, std::size_t last)
    {
        if (nTreeColumns_ > 0) tree_.moveLeaf(last, r);
    }

    //- sum_t coeff_t S_first,t S_second,t over n >= 2 particles (0 for fewer); keeps the
    //  per-term rates and the column totals for propose() (so call it after every change).
    //  With several majorant groups: the sum of the group chosen at the last build().
    double rateSum(std::size_t n)
    {
        double sum = 0.0;
        if (n >= 2) {
            for (std::size_t c = 0; c < nTreeColumns_; ++c) {
                columnTotals_[c] = tree_.total(c);
            }
            lastTerm_ = 0;
            for (std::size_t k = 0; k < nTerms_; ++k) {
                termRate_[k] = termCoeff_[k] * columnTotal(columns_[termFirst_[k]], n)
                               * columnTotal(columns_[termSecond_[k]], n);
                sum += termRate_[k];
                if (termRate_[k] > 0.0) lastTerm_ = k;
            }
        }
        return sum;
    }

    //- A proposal (j1, j2) for u uniform in [0, rateSum(n)), rateSum(n) called since the last
    //  change; j1 == j2 is possible (and rejected by the caller). `particles` lets the store
    //  prefetch the candidates' records.
    void propose(double u, std::size_t n, Rng& rng, const Particle* particles, std::size_t& j1,
                 std::size_t& j2)
    {
        proposeWith<false>(u, n, rng, particles, j1, j2);
    }

    //- Draws made ahead (software pipelining of the event loop). lookAhead() makes
    //  the proposal that propose(u, n, rng, particles) would make now for an rng whose next
    //  words are those of `peek`: the same term, and walks down to their blocks of 8 leaves,
    //  kept. The next proposeAhead(), the same as propose() otherwise, takes their leaves
    //  through QuantizedSumTree::drawNear() (the walks' last steps)
    //  for its own random integers, exact, and walks where that declines (another term, a
    //  change other than one set(), a leaf farther than a few intervals). So the results
    //  are propose()'s bit for bit, and a caller that calls lookAhead() before its change of
    //  the particles has the walks' cache misses overlap that work instead of following it.
    //  Worth it only in a tree too big for the caches: lookaheadPays().
    bool lookaheadPays() const { return nTreeColumns_ > 0 && tree_.lookaheadPays(); }

    void lookAhead(double u, std::size_t n, Rng::Engine& peek, const Particle* particles)
    {
        lookAheadInto(
            u, n, peek, particles, ahead_,
            [this, particles](std::size_t c1, std::uint64_t u1, std::size_t c2, std::uint64_t u2,
                              QuantizedSumTree::Draw& d1, QuantizedSumTree::Draw& d2) {
                tree_.walkPair(c1, u1, c2, u2, particles, sizeof(Particle), d1, d2);
            },
            [this, particles](std::size_t c, std::uint64_t u, QuantizedSumTree::Draw& d) {
                tree_.walk(c, u, particles, sizeof(Particle), d);
            });
    }

    //- The draws made ahead in two halves (QuantizedSumTree::Partial), for a tree where they
    //  pay more than lookAhead() (twoHalvesPay()): lookTwoAhead() makes the walks of the
    //  proposal after the next one down to level 1 (for an rng whose words after the next
    //  proposal's are those of `peek`, with the rates as they are now), and
    //  finishLookAhead(), an event later, finishes them to their blocks as the draws that
    //  lookAhead() would have made for the next proposal (or none, when the term's totals
    //  are empty or the tree has changed by more than one assign() since). Each half's cache
    //  misses are taken an event before its loads.
    bool twoHalvesPay() const { return lookaheadPays() && tree_.twoHalvesPay(); }
    void lookTwoAhead(double u, std::size_t n, Rng::Engine& peek, const Particle* particles)
    {
        lookAheadInto(
            u, n, peek, particles, partial_,
            [this](std::size_t c1, std::uint64_t u1, std::size_t c2, std::uint64_t u2,
                   QuantizedSumTree::Partial& p1, QuantizedSumTree::Partial& p2) {
                tree_.walkPairToNode(c1, u1, c2, u2, p1, p2);
            },
            [this](std::size_t c, std::uint64_t u, QuantizedSumTree::Partial& p) {
                tree_.walkToNode(c, u, p);
            });
    }
    void finishLookAhead(const Particle* particles)
    {
        ahead_.valid = false;
        if (!partial_.valid) return;
        partial_.valid = false;
        const std::size_t term = partial_.term;
        const Column& first = columns_[termFirst_[term]];
        const Column& second = columns_[termSecond_[term]];
        bool ok = true;
        if (!first.uniform) {
            ok = tree_.finishToBlock(first.tree, partial_.first, particles, sizeof(Particle),
                                     ahead_.first);
        }
        if (!second.uniform) {
            ok = ok && tree_.finishToBlock(second.tree, partial_.second, particles,
                                           sizeof(Particle), ahead_.second);
        }
        ahead_.term = term;
        ahead_.valid = ok;
    }

    void proposeAhead(double u, std::size_t n, Rng& rng, const Particle* particles,
                      std::size_t& j1, std::size_t& j2)
    {
        proposeWith<true>(u, n, rng, particles, j1, j2);
    }

    //- The proposal rate of the pair (p1, p2) in the rateSum() units: sum_t coeff_t F_t(p1)
    //  S_t(p2) over the active terms, F and S the store's values of the term's columns. In the tree these are the
    //  quantised majorants QuantizedSumTree::quantised() of phi (* w), so the rate is
    //  >= Khat(z1, z2) (* w2) >= K (* w2), and the target rate (K, times w2 when the second
    //  factors are weighted: SWA) over it is the exact acceptance (thinning); in the bins and
    //  for uniform columns phi (* w) itself, giving Khat(z1, z2) (* w2). Computed from the
    //  particles, without touching the store; p1 and p2 must be in the store as they are now.
    double pairRate(const Particle& p1, const Particle& p2)
    {
        kernel_->basis(p1.type, phi_);
        kernel_->basis(p2.type, phi2_);
        double sum = 0.0;
        for (std::size_t k = 0; k < nTerms_; ++k) {
            sum += termCoeff_[k] * columnValue(columns_[termFirst_[k]], phi_, p1.weight)
                   * columnValue(columns_[termSecond_[k]], phi2_, p2.weight);
        }
        return sum;
    }

    //- pairRate(particles[j1], particles[j2]) for the particles at j1 and j2 of the store,
    //  the same double bit for bit: in the tree the Q's are read from the
    //  leaves (toDouble(q) 2^e, the exact double quantised() computes, by the invariant: every
    //  leaf is the quantisation of its particle's value at the column's current scale, also
    //  after a coarsening, since ceil(ceil(a) / 2^k) = ceil(a / 2^k)) instead of recomputed from
    //  the particles' basis functions: no virtual basis calls and no quantisation per event
    //  (measured: the acceptance was 14 % of an SWA duct run, most of it this arithmetic).
    //  The walks have just loaded (or prefetched) these leaves' lines.
    double pairRateAt(std::size_t j1, std::size_t j2)
    {
        double sum = 0.0;
        for (std::size_t k = 0; k < nTerms_; ++k) {
            sum += termCoeff_[k] * leafValue(columns_[termFirst_[k]], j1)
                   * leafValue(columns_[termSecond_[k]], j2);
        }
        return sum;
    }

    //- The target rate of the pair in the same units: K(z1, z2), times w2 when weighted
    double targetRate(double K, const Particle& p2) const
    {
        return weightedSecond_ ? K * p2.weight : K;
    }

    //- Bytes of the store (the sum tree) currently held
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

    //- propose(), and with Ahead proposeAhead(): the draws made by lookAhead() taken where
    //  they are exact
    template<bool Ahead>
#if defined(__GNUC__)
    __attribute__((always_inline))  // once per event, from one place: as fast as written inline
#endif
    void proposeWith(double u, std::size_t n, Rng& rng, const Particle* particles,
                     std::size_t& j1, std::size_t& j2)
    {
        const std::size_t term = chooseTerm(u);
        const Column& first = columns_[termFirst_[term]];
        const Column& second = columns_[termSecond_[term]];
        const bool ahead = Ahead && ahead_.valid && ahead_.term == term;
        if (Ahead) ahead_.valid = false;
        if (!first.uniform && !second.uniform) {
            // both from the store, the two walks' (candidates') loads overlapping; the
            // random numbers drawn in the same order as one after the other
            const std::uint64_t u1 = rng.uniformIndex(tree_.totalInteger(first.tree));
            const std::uint64_t u2 = rng.uniformIndex(tree_.totalInteger(second.tree));
            const bool have1 = ahead && tree_.drawNear(first.tree, ahead_.first, u1, j1);
            const bool have2 = ahead && tree_.drawNear(second.tree, ahead_.second, u2, j2);
            if (!have1 && !have2) {
                tree_.samplePair(first.tree, u1, second.tree, u2, particles, sizeof(Particle),
                                 j1, j2);
            } else if (!have1) {
                j1 = tree_.sample(first.tree, u1, particles, sizeof(Particle));
            } else if (!have2) {
                j2 = tree_.sample(second.tree, u2, particles, sizeof(Particle));
            }
            tree_.prefetchPath(j1);  // for the change of j1 that follows an acceptance
        } else {
            j1 = sampleColumn(first, n, rng, particles, ahead ? &ahead_.first : nullptr);
#if defined(__GNUC__)
            __builtin_prefetch(&particles[j1 < n ? j1 : 0]);
#endif
            if (nTreeColumns_ > 0) tree_.prefetchPath(j1);
            j2 = sampleColumn(second, n, rng, particles, ahead ? &ahead_.second : nullptr);
        }
    }

    //- The terms of group g made the active ones (termCoeff_ ...), with their columns (a
    //  group of more columns than the tree holds throws std::invalid_argument naming `who`)
    void useGroup(std::size_t g, const std::string& who);

    //- Several groups: the one of the least summed majorant over the n particles (a sample
    //  of chooseSample of them at most) made the active one, before the tree is built
    void chooseGroup(const Particle* particles, std::size_t n);
    static constexpr std::size_t chooseSample = 256;

    //- The term of a proposal at u in [0, rateSum): u past the others' rates (round-off) gives
    //  the last positive one
    std::size_t chooseTerm(double u) const
    {
        for (std::size_t k = 0; k < lastTerm_; ++k) {
            if (u < termRate_[k]) return k;
            u -= termRate_[k];
        }
        return lastTerm_;
    }

    //- lookAhead() and lookTwoAhead() into `into` (valid, term, first, second): the term for
    //  u, and its factors' walks for the integers of peek's next words (pairWalk for two tree
    //  columns, interleaved; else columnWalk for a tree column, and for a uniform one the
    //  predicted particle's record and tree path prefetched)
    template <class Into, class PairWalk, class ColumnWalk>
#if defined(__GNUC__)
    __attribute__((always_inline))
#endif
    void lookAheadInto(double u, std::size_t n, Rng::Engine& peek, const Particle* particles,
                       Into& into, PairWalk pairWalk, ColumnWalk columnWalk)
    {
        const std::size_t term = chooseTerm(u);
        const Column& first = columns_[termFirst_[term]];
        const Column& second = columns_[termSecond_[term]];
        // a term of positive rate (chooseTerm) has positive totals; the guard keeps a walk
        // off an empty column (u = 0 would step past the tree's last nodes) whatever the rates
        into.valid = (first.uniform || tree_.totalInteger(first.tree) > 0)
                     && (second.uniform || tree_.totalInteger(second.tree) > 0);
        if (!into.valid) return;
        into.term = term;
        if (!first.uniform && !second.uniform) {
            const std::uint64_t u1 = Rng::predictedIndex(peek(), tree_.totalInteger(first.tree));
            const std::uint64_t u2 = Rng::predictedIndex(peek(), tree_.totalInteger(second.tree));
            pairWalk(first.tree, u1, second.tree, u2, into.first, into.second);
            return;
        }
        lookAheadColumn(first, n, peek, particles, into.first, columnWalk);
        lookAheadColumn(second, n, peek, particles, into.second, columnWalk);
    }
    template <class Result, class ColumnWalk>
#if defined(__GNUC__)
    __attribute__((always_inline))
#endif
    void lookAheadColumn(const Column& col, std::size_t n, Rng::Engine& peek,
                         const Particle* particles, Result& result, ColumnWalk& columnWalk) const
    {
        if (col.uniform) {
            const std::size_t j = Rng::predictedIndex(peek(), n);
#if defined(__GNUC__)
            __builtin_prefetch(&particles[j]);
#endif
            tree_.prefetchPath(j);
        } else {
            columnWalk(col.tree, Rng::predictedIndex(peek(), tree_.totalInteger(col.tree)), result);
        }
    }

    //- The tree columns of particle p into leaf_, or into `columns`
    void basisColumns(const Particle& p) { basisColumns(p, leaf_); }
    void basisColumns(const Particle& p, double* columns)
    {
        kernel_->basis(p.type, phi_);
        for (std::size_t c = 0; c < nTreeColumns_; ++c) {
            const double v = phi_[treeBasis_[c]];
            columns[c] = treeWeighted_[c] ? v * p.weight : v;
        }
    }

    //- Column col's value for a particle with basis values phi and weight w, as the store
    //  holds it (the same expression as basisColumns(), then the tree's quantisation)
    double columnValue(const Column& col, const double* phi, double w) const
    {
        if (col.uniform) return col.constant;
        const double v = phi[static_cast<std::size_t>(col.basis)];
        const double value = col.weighted ? v * w : v;  // as basisColumns()
        return tree_.quantised(col.tree, value);
    }

    //- Column col's Q of leaf j as the tree holds it (the tree only)
    double leafValue(const Column& col, std::size_t j) const
    {
        return col.uniform ? col.constant : tree_.value(j, col.tree);
    }

    //- The column's total as of rateSum() (columnTotals_ filled first)
    double columnTotal(const Column& col, std::size_t n) const
    {
        if (col.uniform) return col.constant * static_cast<double>(n);
        return columnTotals_[col.tree];
    }

    //- A draw from one column; `ahead` (or null): the tree column's draw made by lookAhead()
    std::size_t sampleColumn(const Column& col, std::size_t n, Rng& rng,
                             const Particle* particles,
                             const QuantizedSumTree::Draw* ahead) const
    {
        if (col.uniform) return static_cast<std::size_t>(rng.uniformIndex(n));
        const std::uint64_t u = rng.uniformIndex(tree_.totalInteger(col.tree));
        std::size_t j = 0;
        if (ahead && tree_.drawNear(col.tree, *ahead, u, j)) return j;
        return tree_.sample(col.tree, u, particles, sizeof(Particle));
    }

    bool weightedSecond_;
    const CoagulationKernel* kernel_ = nullptr;
    //- Fixed arrays, not vectors: read on every event without an indirection (measured with
    //  the tree's per-column arrays, callgrind: 65 fewer instructions an event at 1e5; the
    //  time there did not change, the loop being bound by its chain of dependences)
    Column columns_[2 * maxBasis];
    std::size_t nColumns_ = 0;
    std::size_t nTreeColumns_ = 0;
    std::size_t treeBasis_[QuantizedSumTree::maxColumns] = {};  // per tree column: its basis
    bool treeWeighted_[QuantizedSumTree::maxColumns] = {};      // per tree column: phi * w
    std::size_t nTerms_ = 0;
    double termCoeff_[maxTerms] = {};
    std::size_t termFirst_[maxTerms] = {};   // column of phi_first
    std::size_t termSecond_[maxTerms] = {};  // column of phi_second (* w for SWA)
    double termRate_[maxTerms] = {};
    double phi_[maxBasis] = {};
    double phi2_[maxBasis] = {};
    std::size_t lastTerm_ = 0;       // rateSum(): the last term with a positive rate
    //- All the majorant groups' terms (group g's are [groupBegin_[g], groupBegin_[g + 1]),
    //  with their basis functions), and the group whose terms and columns are the active
    //  ones above. One group: the active terms are all the terms.
    std::size_t nGroups_ = 1;
    std::size_t groupBegin_[maxGroups + 1] = {};
    std::size_t activeGroup_ = 0;
    double allCoeff_[maxGroups * maxTerms] = {};
    int allFirst_[maxGroups * maxTerms] = {};
    int allSecond_[maxGroups * maxTerms] = {};
    double constantPhi_[maxBasis] = {};  // the basis at a default particle: the constant ones
    //- lookAhead()'s (or finishLookAhead()'s) draws for the next proposeAhead(): its term and
    //  the tree columns' walks to their blocks
    struct Ahead {
        bool valid = false;
        std::size_t term = 0;
        QuantizedSumTree::Draw first, second;
    };
    Ahead ahead_;
    //- lookTwoAhead()'s walks to level 1, for finishLookAhead()
    struct Partials {
        bool valid = false;
        std::size_t term = 0;
        QuantizedSumTree::Partial first, second;
    };
    Partials partial_;
    double leaf_[QuantizedSumTree::maxColumns] = {};          // one particle's tree columns
    double columnTotals_[QuantizedSumTree::maxColumns] = {};  // column totals as of rateSum()
    QuantizedSumTree tree_;
};

} // namespace coag

#endif
