// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_NANBUMETHOD_HPP
#define COAGULATION_NANBUMETHOD_HPP

#include "coagulation/kernels/CoagulationKernel.hpp"
#include "coagulation/random/Rng.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace coag {

struct NanbuParameters {
    double alpha = 0.1;           //!< discretization parameter, in (0,1] (2.13)
    std::size_t maxSize = 4096;   //!< largest size kept; merges beyond it are dropped (counted)
};

struct NanbuStatistics {
    std::uint64_t steps = 0;
    std::uint64_t reactions = 0;            //!< particles that chose to react (step 3.1)
    std::uint64_t truncatedComponents = 0;  //!< components N'_l < 0 set to 0 (2.19)
    std::uint64_t truncatedParticles = 0;   //!< sum of the removed negative parts
    std::uint64_t doublings = 0;            //!< doublings (2.20)-(2.21)
    std::uint64_t overflowParticles = 0;    //!< merged clusters larger than maxSize (dropped)
};

//- Nanbu-type particle method for the homogeneous discrete Smoluchowski equation
//  (Kolodko, Sabelfeld & Wagner, §2.1, eqs 2.12-2.22). State: counts N_l of particles of
//  size l and the normalizing c_k; N_l/c_k approximates n_l(t_k). One step:
//    Delta_k = alpha / max_{1 <= i <= min(2^k L0, maxSize)} sum_j N_j/c_k K_ij        (2.12)
//    each particle of size l reacts with probability P_l = 1/2 Delta_k sum_j N_j/c_k K_lj,
//    with a partner of size m ~ N_m K_lm / sum_j N_j K_lj, and then
//    N'_l -= 1, N'_m -= 1, N'_{l+m} += 1                                            (2.16-2.18)
//    truncation N_l = max(0, N'_l) (2.19); doubling N_l *= 2, c *= 2 when sum N_l <= N/2,
//    N the initial number of particles (2.20-2.21).
//  Work per step: the number of reacting particles of size l is one binomial draw, and their
//  partner sizes one multinomial draw (sequential binomials over the occupied sizes), so a
//  step costs O(R D + D^2) kernel evaluations (D occupied sizes, R = min(2^k L0, maxSize)),
//  independent of the number of particles.
//  The kernel is evaluated on ParticleType{mass = l}.
class NanbuSmoluchowski {
public:
    //- initialCounts[l-1] = N_l(0); c0 > 0 is the initial normalizing constant.
    NanbuSmoluchowski(const CoagulationKernel& kernel, const std::vector<std::int64_t>& initialCounts,
                      double c0, const NanbuParameters& params = {});

    //- Counts N_l(0) = round(c0 n0_l) with c0 = N / sum n0 (2.23).
    static NanbuSmoluchowski fromDensity(const CoagulationKernel& kernel,
                                         const std::vector<double>& initialDensity,
                                         std::int64_t N, const NanbuParameters& params = {});

    //- One step (2.12)-(2.22); returns Delta_k. Throws std::runtime_error when empty.
    double step(Rng& rng);

    double time() const { return t_; }
    std::size_t stepIndex() const { return k_; }
    double normalization() const { return c_; }  //!< c_k
    std::int64_t count(std::size_t l) const;       //!< N_l (0 outside the stored range)
    double density(std::size_t l) const { return static_cast<double>(count(l)) / c_; }
    std::vector<double> densities() const;         //!< N_l/c_k, index l-1, up to largestSize()
    std::int64_t totalCount() const;
    std::int64_t initialTotal() const { return N0_; }
    std::size_t largestSize() const;
    const NanbuStatistics& statistics() const { return stats_; }
    const NanbuParameters& parameters() const { return params_; }

private:
    const CoagulationKernel& kernel_;
    NanbuParameters params_;
    std::vector<std::int64_t> N_;   // index l-1
    std::vector<std::int64_t> Np_;  // work: N'
    std::vector<double> rate_;      // work: sum_j N_j K_ij for i = 1..range
    std::vector<std::size_t> occupied_;
    double c_;
    std::int64_t N0_ = 0;
    std::size_t L0_ = 1;
    double t_ = 0.0;
    std::size_t k_ = 0;
    NanbuStatistics stats_;
};

} // namespace coag

#endif
