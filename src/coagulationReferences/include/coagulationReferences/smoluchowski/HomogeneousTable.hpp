// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_HOMOGENEOUSTABLE_HPP
#define COAGULATION_HOMOGENEOUSTABLE_HPP

#include "coagulation/kernels/CoagulationKernel.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace coag {

//- The normalised homogeneous problem of Kolodko, Sabelfeld and Wagner (2.32),
//      df_l/ds = 1/2 sum_{i+j=l} k_ij f_i f_j - f_l sum_i k_il f_i,   k_ij = K_ij / K_11,
//      f_1(0) = 1, f_l(0) = 0 (l >= 2),
//  solved once and tabulated on a mesh of the scaled time s in [0, sMax]. By (2.33) the
//  solution from monomers of density n is n_l(t) = n f_l(n K_11 t), so one table serves every
//  initial density along every trajectory (§4.1, (4.4)).
//
//  Truncation: sizes 1..maxSize (clusters that would be larger are lost, as in
//  DiscreteSmoluchowski); lostMass() = 1 - sum_l l f_l(sMax) is the mass that left the
//  truncated system by sMax (it bounds the truncation error of every f_l). The tutorials' table
//  (Saffman-Turner, sMax = beta t' = 0.0039 * 55 = 0.2145) keeps 64 sizes and loses 1e-16.
//
//  Two constructions:
//  - fromOde: the truncated system integrated by the adaptive Dormand-Prince 5(4) pair of
//    DiscreteSmoluchowski (relTol 1e-11, absTol 1e-15) node by node on a uniform mesh of
//    `intervals` intervals; the derivative at every node is the right hand side there, and
//    between nodes f is the cubic Hermite interpolant of values and derivatives (error O(h^4)).
//  - fromNanbu: the paper's alternative, the Nanbu particle method (§2.1, NanbuMethod.hpp) from N
//    monomers (c0 = N, (2.24)) with parameter alpha, in the normalised kernel; the nodes are the
//    method's own step times t_k (2.14) up to the first one >= sMax, the values N_l/c_k, and
//    f is linear between nodes. (§4.1 takes the value at the first node at or after the time;
//    linear interpolation is a refinement of that.)
class NormalisedSmoluchowskiTable {
public:
    static NormalisedSmoluchowskiTable fromOde(const CoagulationKernel& kernel, double sMax,
                                               std::size_t maxSize, std::size_t intervals);
    static NormalisedSmoluchowskiTable fromNanbu(const CoagulationKernel& kernel, double sMax,
                                                 std::size_t maxSize, std::int64_t N,
                                                 double alpha, std::uint64_t seed);

    std::size_t maxSize() const { return L_; }
    double sMax() const { return s_.back(); }
    std::size_t nodes() const { return s_.size(); }
    double node(std::size_t m) const { return s_[m]; }
    bool hermite() const { return !dF_.empty(); }

    //- f_l(s), l >= 1 (0 for l > maxSize). Throws std::out_of_range unless 0 <= s <= sMax.
    double density(std::size_t l, double s) const;
    //- f_1(s) .. f_n(s) into f (n <= maxSize), the sum over all sizes sum_l f_l(s) into *total
    //  and sum_l l f_l(s) into *mass (either pointer may be null).
    void evaluate(double s, std::size_t n, double* f, double* total, double* mass) const;
    double total(double s) const;
    double mass(double s) const;
    //- 1 - sum_l l f_l(sMax)
    double lostMass() const { return 1.0 - mass(sMax()); }

private:
    NormalisedSmoluchowskiTable() = default;
    // interval m with s_m <= s <= s_{m+1} and the weights of the four Hermite / two linear terms
    std::size_t locate(double s) const;

    std::size_t L_ = 0;
    std::vector<double> s_;
    // rows of L_ + 2 per node: f_1..f_L, total, mass (node-major: node m at [m (L_+2)])
    std::vector<double> F_;
    std::vector<double> dF_;   // derivatives, same layout (empty: linear interpolation)
};

} // namespace coag

#endif
