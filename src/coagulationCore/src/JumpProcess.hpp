// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_JUMPPROCESS_HPP
#define COAGULATION_JUMPPROCESS_HPP

// Private to the core: the exact jump process in one cell that SWA (SwaAlgorithm.cpp) and
// DSA1/DSA2 (DsaAlgorithm.cpp) share. They differ only in the Jump policy:
//
//   static constexpr const char* name;      "SWA", "DSA1", "DSA2"
//   static constexpr bool equalWeights;     DSA: all weights equal (pulled out of the sums,
//                                           halving halves the volume, closed-cell doubling)
//   void coagulate(pop, j1, j2, rng, sampler)   the accepted jump on the pair (j1, j2),
//                                           keeping the sampler's leaves in step

#include "coagulation/CellAlgorithm.hpp"
#include "coagulation/MajorantSampler.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {
namespace detail {

template <class Jump>
class JumpProcess final : public CellAlgorithm {
public:
    JumpProcess(const CoagulationKernel& kernel, const InceptionModel& inception,
                const NumberControl& control)
        : CellAlgorithm(kernel), inception_(inception), control_(control),
          sampler_(!Jump::equalWeights)
    {
        sampler_.configure(kernel, "coag::makeCellAlgorithm");
    }

    std::string name() const override { return Jump::name; }

    using CellAlgorithm::advance;
    void advance(CellPopulation& pop, const CoagulationKernel& kernel, double dt, Rng& rng,
                 StepStatistics& stats) override;

    std::size_t workspaceBytes() const override { return sampler_.memoryBytes(); }

private:
    //- DSA's doubling applies in closed cells only (see NumberControl.hpp)
    bool closedControl() const
    {
        return Jump::equalWeights && control_.minParticles > 0 && inception_.rate == 0.0;
    }

    void halve(CellPopulation& pop, Rng& rng, StepStatistics& stats)
    {
        halvePopulation(pop, Jump::equalWeights, rng, stats);
        sampler_.build(pop.particles, sampler_.capacity());
    }

    void duplicate(CellPopulation& pop, StepStatistics& stats)
    {
        duplicatePopulation(pop, stats);
        sampler_.build(pop.particles, sampler_.capacity());
    }

    //- The common weight of a DSA population (checked), or the inception weight
    double commonWeight(const std::vector<Particle>& P) const;

    Jump jump_;
    InceptionModel inception_;
    NumberControl control_;
    MajorantSampler sampler_;
};

template <class Jump>
double JumpProcess<Jump>::commonWeight(const std::vector<Particle>& P) const
{
    if (P.empty()) return inception_.weight;
    const double w = P.front().weight;
    const std::string who = std::string("coag::") + Jump::name + "::advance: ";
    if (!(w > 0.0) || !std::isfinite(w)) {
        throw std::invalid_argument(who + "particle weights must be finite and > 0");
    }
    for (const Particle& p : P) {
        if (p.weight != w) {
            throw std::invalid_argument(who + "DSA requires all particle weights to be equal");
        }
    }
    if (inception_.rate > 0.0 && w != inception_.weight) {
        throw std::invalid_argument(who + "DSA with inception requires the particle weights to "
                                          "equal the inception weight");
    }
    return w;
}

template <class Jump>
void JumpProcess<Jump>::advance(CellPopulation& pop, const CoagulationKernel& kernel, double dt,
                                Rng& rng, StepStatistics& stats)
{
    const std::string who = std::string("coag::") + Jump::name + "::advance";
    if (!(dt >= 0.0) || !std::isfinite(dt)) {
        std::ostringstream os;
        os << who << ": dt must be finite and >= 0, got " << dt;
        throw std::invalid_argument(os.str());
    }
    if (!(pop.volume > 0.0) || !std::isfinite(pop.volume)) {
        std::ostringstream os;
        os << who << ": cell volume must be finite and > 0, got " << pop.volume;
        throw std::invalid_argument(os.str());
    }
    if (&kernel != &sampler_.kernel()) sampler_.configure(kernel, who);
    std::vector<Particle>& P = pop.particles;
    const double w = Jump::equalWeights ? commonWeight(P) : 0.0;

    // Number control on entry (the caller may have moved particles in or out).
    while (control_.maxParticles > 0 && P.size() > control_.maxParticles) {
        halvePopulation(pop, Jump::equalWeights, rng, stats);
    }
    if (closedControl()) {
        while (!P.empty() && P.size() < control_.minParticles) duplicatePopulation(pop, stats);
    }

    // Reserve for the expected number of inceptions so that no event allocates.
    const double inceptionPerVolume = inception_.rate / inception_.weight;
    std::size_t capacity = P.size();
    {
        const double expected = inceptionPerVolume * pop.volume * dt;
        if (expected > 0.0) {
            double extra = expected + 5.0 * std::sqrt(expected) + 16.0;
            extra = std::min(extra, 16777216.0);
            capacity += static_cast<std::size_t>(extra);
            if (control_.maxParticles > 0) {
                capacity = std::min(capacity, std::max(P.size(), control_.maxParticles + 1));
            }
        }
    }
    P.reserve(capacity);
    sampler_.build(P, capacity);

    // Pair rates summed over ordered pairs: SWA K w2 / V (eq 22; w2 inside the sampler's
    // second factors), DSA K w / (2V) (each unordered pair at K w / V, eqs 12, 16-17).
    const double pairFactor = Jump::equalWeights ? 0.5 * w : 1.0;
    double t = 0.0;

    for (;;) {
        const std::size_t n = P.size();
        const double V = pop.volume;
        const double inceptionRate = inceptionPerVolume * V;  // eq 10 (DSA), eq 20 (SWA)
        const double scale = pairFactor / V;
        const double coagulationRate = sampler_.rateSum(n) * scale;
        const double totalRate = inceptionRate + coagulationRate;
        if (!(totalRate > 0.0)) break;
        if (!std::isfinite(totalRate)) {
            throw std::runtime_error(who + ": total event rate is not finite (gelation?)");
        }
        if (totalRate * (dt - t) > maxExpectedEvents) {
            std::ostringstream os;
            os << who << ": " << totalRate * (dt - t)
               << " events expected in the rest of the step (limit " << maxExpectedEvents
               << ", " << n << " particles, volume " << V
               << "): the kernel or inception rate is far too large for the step, or the "
                  "population is past gelation";
            throw std::runtime_error(os.str());
        }
        // Exact waiting time of the jump process (Gillespie), rates fixed until the next jump
        t += rng.exponential(totalRate);
        if (!(t <= dt)) break;

        double u = rng.uniform() * totalRate;
        if (u < inceptionRate) {
            // ---- inception: (x, z, w_incep), eq 9 (DSA, w = 1 there) / eq 19 (SWA)
            P.push_back(Particle{inception_.type, inception_.weight, -1});
            sampler_.append(P.back(), P.size() - 1);
            ++stats.inceptions;
            stats.inceptedMass += inception_.weight * inception_.type.mass;
            while (control_.maxParticles > 0 && P.size() > control_.maxParticles) {
                halve(pop, rng, stats);
            }
            continue;
        }

        // ---- coagulation proposal from the majorant
        std::size_t j1 = 0;
        std::size_t j2 = 0;
        sampler_.propose((u - inceptionRate) / scale, n, rng, P.data(), j1, j2);
        if (j1 == j2 || j1 >= n || j2 >= n) {
            ++stats.fictitious;
            continue;
        }

        // Acceptance K/Khat (a rejection is a fictitious jump)
        const double majorant = sampler_.majorant(P[j1].type, P[j2].type);
        const double K = kernel(P[j1].type, P[j2].type);
        if (K < majorant) {
            if (!(rng.uniform() * majorant < K)) {
                ++stats.fictitious;
                continue;
            }
        } else if (!(K <= majorant * (1.0 + 1e-9))) {
            std::ostringstream os;
            os << who << ": kernel '" << kernel.name() << "' value " << K
               << " exceeds its majorant " << majorant << " at masses " << P[j1].type.mass
               << ", " << P[j2].type.mass;
            if (!std::isfinite(K) || !std::isfinite(majorant)) {
                os << " (non-finite values: has the system gelled?)";
                throw std::runtime_error(os.str());
            }
            throw std::logic_error(os.str());
        }

        // ---- accepted coagulation: the algorithm's jump
        ++stats.coagulations;
        jump_.coagulate(pop, j1, j2, rng, sampler_);
        if (closedControl()) {
            while (!P.empty() && P.size() < control_.minParticles) duplicate(pop, stats);
        }
    }
}

//- The factories of the algorithms (SwaAlgorithm.cpp, DsaAlgorithm.cpp)
std::unique_ptr<CellAlgorithm> makeSwa(const CoagulationKernel&, const InceptionModel&,
                                       const NumberControl&);
std::unique_ptr<CellAlgorithm> makeDsa1(const CoagulationKernel&, const InceptionModel&,
                                        const NumberControl&);
std::unique_ptr<CellAlgorithm> makeDsa2(const CoagulationKernel&, const InceptionModel&,
                                        const NumberControl&);

} // namespace detail
} // namespace coag

#endif
