// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_HOMOGENEOUSTABLE_HPP
#define COAGULATION_HOMOGENEOUSTABLE_HPP

#include "coagulation/kernels/CoagulationKernel.hpp"

#include <Eigen/Dense>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace coag {

//- The homogeneous Smoluchowski problem from monomers, solved once and tabulated in a scaled
//  time, so that one table serves every initial density along every trajectory of the
//  Lagrangian methods. Two scalings of the same solution:
//  - normalised (Kolodko, Sabelfeld & Wagner (2.32)-(2.33), §4.1 (4.4)):
//        df_l/ds = 1/2 sum_{i+j=l} k_ij f_i f_j - f_l sum_i k_il f_i,   k_ij = K_ij / K_11,
//        f_1(0) = 1, f_l(0) = 0 (l >= 2);   n_l(t) = n f_l(n K_11 t) from monomers of density n;
//  - kernel (Sabelfeld & Kolodko (18)): u_l(tau) for K itself, du/dtau = K(u), u_l(0) = delta_1l;
//        rho_l(t; delta_1l n) = n u_l(n t). Also for a kernel with K_11 = 0 (no coagulation).
//  solution(n, t, out) gives n_l(t) in either scaling; evaluate() the tabulated f (or u).
//
//  Truncation: sizes 1..maxSize (clusters that would be larger are lost, as in
//  DiscreteSmoluchowski); lostMass() = 1 - sum_l l f_l(sMax) is the mass that left the
//  truncated system by sMax (it bounds the truncation error of every f_l). Sizes
//  1..sizes() are kept (Options::storedSizes; all by default), with the totals over all sizes.
//
//  Two constructions:
//  - fromOde: the truncated system integrated by the adaptive Dormand-Prince 5(4) pair of
//    DiscreteSmoluchowski (Options' tolerances) node by node, on a uniform mesh of `intervals`
//    intervals or a graded one, s_m = sMax (m/intervals)^2, which resolves the start, where
//    f_l ~ s^(l-1) is no cubic (the first interval is sMax/intervals^2 long); the derivative
//    at every node is the right hand side there, and between nodes f is the cubic Hermite
//    interpolant of values and derivatives (error O(h^4)), cut at 0 from below.
//  - fromNanbu: the normalised problem by the Nanbu particle method (§2.1, NanbuMethod.hpp)
//    from N monomers (c0 = N, (2.24)) with parameter alpha; the nodes are the method's own
//    step times t_k (2.14) up to the first one >= sMax, the values N_l/c_k, and f is linear
//    between nodes. (§4.1 takes the value at the first node at or after the time; linear
//    interpolation is a refinement of that.)
class HomogeneousTable {
public:
    enum class Scaling { normalised, kernel };
    enum class Mesh { uniform, graded };
    struct Options {
        Scaling scaling = Scaling::normalised;
        Mesh mesh = Mesh::uniform;
        std::size_t storedSizes = 0;  //- sizes kept (0: all maxSize)
        double relTol = 1e-11;        //- DiscreteSmoluchowski's tolerances
        double absTol = 1e-15;
    };

    static HomogeneousTable fromOde(const CoagulationKernel& kernel, double sMax,
                                    std::size_t maxSize, std::size_t intervals,
                                    const Options& options);
    //- fromOde with the default Options: normalised, uniform mesh, every size kept
    static HomogeneousTable fromOde(const CoagulationKernel& kernel, double sMax,
                                    std::size_t maxSize, std::size_t intervals);
    static HomogeneousTable fromNanbu(const CoagulationKernel& kernel, double sMax,
                                      std::size_t maxSize, std::int64_t N, double alpha,
                                      std::uint64_t seed);

    std::size_t maxSize() const { return L_; }
    //- The sizes kept, 1..sizes()
    std::size_t sizes() const { return stored_; }
    double sMax() const { return s_.back(); }
    std::size_t nodes() const { return s_.size(); }
    double node(std::size_t m) const { return s_[m]; }
    bool hermite() const { return !dF_.empty(); }
    //- The scaled time per density and time: K_11 (normalised) or 1 (kernel)
    double timeScale() const { return timeScale_; }

    //- f_1(s) .. f_n(s) into f (n <= sizes()), the sum over all sizes sum_l f_l(s) into *total
    //  and sum_l l f_l(s) into *mass (either pointer may be null). Throws std::out_of_range
    //  unless 0 <= s <= sMax.
    void evaluate(double s, std::size_t n, double* f, double* total, double* mass) const;
    //- f_l(s), l >= 1 (0 for l > maxSize; std::out_of_range for a size not kept)
    double density(std::size_t l, double s) const;
    double total(double s) const;
    double mass(double s) const;
    //- 1 - sum_l l f_l(sMax)
    double lostMass() const { return 1.0 - mass(sMax()); }

    //- The homogeneous solution at time t from monomers of density n >= 0: n f_l(timeScale n t),
    //  l = 1..sizes(), into out (0 for n = 0)
    void solution(double n, double t, double* out) const;

    //- K_ij of the kernel itself (not normalised), i, j = 1..sizes()
    const Eigen::MatrixXd& kernelMatrix() const { return K_; }

private:
    HomogeneousTable() = default;
    // interval m with s_m <= s <= s_{m+1}
    std::size_t locate(double s) const;

    std::size_t L_ = 0;
    std::size_t stored_ = 0;
    double timeScale_ = 1.0;
    std::vector<double> s_;
    // rows of stored_ + 2 per node: f_1..f_stored, total, mass (node m at [m (stored_+2)])
    std::vector<double> F_;
    std::vector<double> dF_;   // derivatives, same layout (empty: linear interpolation)
    Eigen::MatrixXd K_;
};

} // namespace coag

#endif
