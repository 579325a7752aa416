// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_EXACTSOLUTIONS_HPP
#define COAGULATION_EXACTSOLUTIONS_HPP

#include <array>
#include <cstddef>

//- Closed-form solutions of the Smoluchowski equation
//      dn/dt = I + 1/2 sum_{i+j} K n_i n_j - n sum K n
//  used as test references. "Monodisperse": n_k(0) = N0 delta_{k1} (unit-mass monomers).
//  Moments are m_j = sum_k k^j n_k, returned as {m0, m1, m2, m3}.
namespace coag {
namespace exact {

//- K = K0: n_k = N0 tau^{k-1} / (1+tau)^{k+1}, tau = K0 N0 t / 2.
double constantKernelDensity(double K0, double N0, double t, std::size_t k);
//- m0 = N0/(1+tau), m1 = N0, m2 = N0 (1 + K0 N0 t), m3 = N0 (1 + 3T + 3T^2/2), T = K0 N0 t.
std::array<double, 4> constantKernelMoments(double K0, double N0, double t);

//- K = K0 with growth dm/dt = sigma m of every particle, monodisperse start: the closed
//  moment equations dm0/dt = -K0 m0^2/2, dm1/dt = sigma m1, dm2/dt = 2 sigma m2 + K0 m1^2,
//  dm3/dt = 3 sigma m3 + 3 K0 m1 m2 give m0 = N0/(1+T/2), m1 = N0 e^{st},
//  m2 = N0 e^{2st} (1 + T), m3 = N0 e^{3st} (1 + 3T + 3T^2/2), T = K0 N0 t, s = sigma.
std::array<double, 4> constantKernelLinearGrowthMoments(double K0, double N0, double sigma,
                                                        double t);
//- K = K0 with growth dm/dt = g of every particle, monodisperse start: m0 = N0/(1+T/2),
//  m1 = N0 + (2 g / K0) ln(1 + T/2) (dm1/dt = g m0), T = K0 N0 t; {m0, m1}.
std::array<double, 2> constantKernelConstantGrowthMoments(double K0, double N0, double g,
                                                          double t);

//- K = K0 (x+y) (Golovin): n_k = N0 (1-s) (k s)^{k-1} e^{-k s} / k!, s = 1 - exp(-K0 N0 t).
double additiveKernelDensity(double K0, double N0, double t, std::size_t k);
//- m0 = N0 e^{-T}, m1 = N0, m2 = N0 e^{2T}, m3 = N0 e^{3T} (3 e^T - 2), T = K0 N0 t.
std::array<double, 4> additiveKernelMoments(double K0, double N0, double t);

//- K = K0 x y before gelation (T = K0 N0 t < 1; otherwise std::domain_error):
//  n_k = N0 k^{k-2} T^{k-1} e^{-k T} / k!.
double multiplicativeKernelDensity(double K0, double N0, double t, std::size_t k);
//- m0 = N0 - K0 N0^2 t / 2, m1 = N0, m2 = N0 / (1 - T), m3 = N0 / (1 - T)^3.
std::array<double, 4> multiplicativeKernelMoments(double K0, double N0, double t);

//- K = K0 with a constant monomer source I (per unit volume and time), starting empty:
//  m0 = sqrt(2I/K0) tanh(t sqrt(I K0 / 2)), m1 = I t, m2 = I t + K0 I^2 t^3 / 3,
//  m3 = I t + K0 I^2 t^3 + K0^2 I^3 t^5 / 5.
std::array<double, 4> constantKernelSourceMoments(double K0, double I, double t);

} // namespace exact
} // namespace coag

#endif
