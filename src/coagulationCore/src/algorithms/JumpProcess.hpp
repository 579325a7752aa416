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
//   static constexpr bool lookahead;        whether the event loop may draw proposals ahead
//                                           (the modes below): for a jump that changes the
//                                           sampler by one set() (SWA); a removal by swap
//                                           (DSA) leaves such draws unusable
//   void coagulate(pop, j1, j2, rng, sampler)   the accepted jump on the pair (j1, j2),
//                                           keeping the sampler's leaves in step

#include "coagulation/algorithms/CellAlgorithm.hpp"
#include "coagulation/algorithms/EventLoop.hpp"
#include "coagulation/sampling/MajorantSampler.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {
namespace detail {

// The event loop's modes, the policies of JumpProcess::events. A mode that draws ahead
// makes, during an event, the draws of a later proposal from the engine's words that this
// proposal will take (EventWords: past this event's acceptance, wordsToProposal more, then
// the proposal's choice), so that their cache misses overlap the event's work instead of
// following it; proposeAhead() keeps only what is exact, so every mode gives the same
// events. Worth it only in a sum tree too big for the caches (pays()).

//- Every proposal walks the tree when it is made
struct NotAhead {
    static constexpr bool drawsAhead = false;
    static constexpr int wordsToProposal = 0;
    static bool pays(const MajorantSampler&) { return true; }
    static void finishEarlier(MajorantSampler&, const Particle*) {}
    static void drawAhead(MajorantSampler&, double, std::size_t, Rng::Engine&, const Particle*) {}
};

//- The next proposal walks the tree to its blocks during this event
//  (MajorantSampler::lookAhead); its words follow the next waiting time
struct AheadInOnePiece {
    static constexpr bool drawsAhead = true;
    static constexpr int wordsToProposal = EventWords::waitingTime;
    static bool pays(const MajorantSampler& s) { return s.lookaheadPays(); }
    static void finishEarlier(MajorantSampler&, const Particle*) {}
    static void drawAhead(MajorantSampler& s, double u, std::size_t n, Rng::Engine& peek,
                          const Particle* P)
    {
        s.lookAhead(u, n, peek, P);
    }
};

//- The proposal after the next walks down to level 1 during this event
//  (MajorantSampler::lookTwoAhead) and the next one finishes its walks, begun an event
//  earlier, to their blocks (finishLookAhead); its words follow the next event and the
//  waiting time after it
struct AheadInTwoHalves {
    static constexpr bool drawsAhead = true;
    static constexpr int wordsToProposal = EventWords::event + EventWords::waitingTime;
    static bool pays(const MajorantSampler& s) { return s.twoHalvesPay(); }
    static void finishEarlier(MajorantSampler& s, const Particle* P) { s.finishLookAhead(P); }
    static void drawAhead(MajorantSampler& s, double u, std::size_t n, Rng::Engine& peek,
                          const Particle* P)
    {
        s.lookTwoAhead(u, n, peek, P);
    }
};

template <class Jump>
class JumpProcess final : public CellAlgorithm {
public:
    JumpProcess(const CoagulationKernel& kernel, const InceptionModel& inception,
                const NumberControl& control, DrawsAhead drawsAhead)
        : CellAlgorithm(kernel), inception_(inception), control_(control),
          sampler_(!Jump::equalWeights),
          drawsAhead_(Jump::lookahead && drawsAhead == DrawsAhead::whereTheyPay)
    {
        sampler_.configure(kernel, "coag::makeCellAlgorithm");
    }

    std::string name() const override { return Jump::name; }

    using CellAlgorithm::advance;
    void advance(CellPopulation& pop, const CoagulationKernel& kernel, double inceptionRate,
                 double dt, Rng& rng, StepStatistics& stats) override;

    const InceptionModel& inception() const override { return inception_; }

    std::size_t workspaceBytes() const override { return sampler_.memoryBytes(); }

private:
    //- DSA's doubling applies in closed cells only (see NumberControl.hpp)
    bool closedControl(double inceptionRate) const
    {
        return Jump::equalWeights && control_.minParticles > 0 && inceptionRate == 0.0;
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
    double commonWeight(const ParticleVector& P, double inceptionRate) const;

    static std::string who() { return std::string("coag::") + Jump::name + "::advance"; }

    //- dt >= 0, a positive volume and a finite inception rate >= 0, else
    //  std::invalid_argument
    static void checkArguments(const CellPopulation& pop, double inceptionRate, double dt);

    //- Room for the particles and the inceptions expected over dt (mean + 5 sd + 16)
    std::size_t expectedCapacity(const CellPopulation& pop, double inceptionRate,
                                 double dt) const;

    //- A finite rate, and not more than maxExpectedEvents in the rest of the step (else
    //  badRate's std::runtime_error)
    static void checkRate(double totalRate, double remaining, const CellPopulation& pop)
    {
        if (!std::isfinite(totalRate) || totalRate * remaining > maxExpectedEvents) {
            badRate(totalRate, remaining, pop);
        }
    }
    [[noreturn]] static void badRate(double totalRate, double remaining,
                                     const CellPopulation& pop);

    //- The events of one step from t = 0 to dt, the sampler built, in the given mode
    //  (NotAhead, AheadInOnePiece, AheadInTwoHalves)
    template <class Mode>
    void events(CellPopulation& pop, const CoagulationKernel& kernel, double inceptionRate,
                double w, double dt, Rng& rng, StepStatistics& stats);

    //- The acceptance of a proposed pair: K (w2) over its proposal rate (MajorantSampler::
    //  pairRate, Khat (w2) from the tree's integer majorants); a K above its majorant throws
    bool accepted(std::size_t j1, const Particle& p1, std::size_t j2, const Particle& p2,
                  const CoagulationKernel& kernel, Rng& rng);

    Jump jump_;
    InceptionModel inception_;
    NumberControl control_;
    MajorantSampler sampler_;
    bool drawsAhead_;
};

template <class Jump>
double JumpProcess<Jump>::commonWeight(const ParticleVector& P,
                                       double inceptionRate) const
{
    if (P.empty()) return inception_.weight;
    const double w = P.front().weight;
    if (!(w > 0.0) || !std::isfinite(w)) {
        throw std::invalid_argument(who() + ": particle weights must be finite and > 0");
    }
    for (const Particle& p : P) {
        if (p.weight != w) {
            throw std::invalid_argument(who() + ": DSA requires all particle weights to be equal");
        }
    }
    if (inceptionRate > 0.0 && w != inception_.weight) {
        throw std::invalid_argument(who() + ": DSA with inception requires the particle weights "
                                            "to equal the inception weight");
    }
    return w;
}

template <class Jump>
void JumpProcess<Jump>::checkArguments(const CellPopulation& pop, double inceptionRate,
                                       double dt)
{
    if (!(inceptionRate >= 0.0) || !std::isfinite(inceptionRate)) {
        std::ostringstream os;
        os << who() << ": inception rate must be finite and >= 0, got " << inceptionRate;
        throw std::invalid_argument(os.str());
    }
    if (!(dt >= 0.0) || !std::isfinite(dt)) {
        std::ostringstream os;
        os << who() << ": dt must be finite and >= 0, got " << dt;
        throw std::invalid_argument(os.str());
    }
    if (!(pop.volume > 0.0) || !std::isfinite(pop.volume)) {
        std::ostringstream os;
        os << who() << ": cell volume must be finite and > 0, got " << pop.volume;
        throw std::invalid_argument(os.str());
    }
}

template <class Jump>
std::size_t JumpProcess<Jump>::expectedCapacity(const CellPopulation& pop, double inceptionRate,
                                                double dt) const
{
    const std::size_t n = pop.particles.size();
    const double expected = inceptionRate / inception_.weight * pop.volume * dt;
    if (!(expected > 0.0)) return n;
    double extra = expected + 5.0 * std::sqrt(expected) + 16.0;
    extra = std::min(extra, 16777216.0);
    std::size_t capacity = n + static_cast<std::size_t>(extra);
    if (control_.maxParticles > 0) {
        capacity = std::min(capacity, std::max(n, control_.maxParticles + 1));
    }
    return capacity;
}

template <class Jump>
void JumpProcess<Jump>::badRate(double totalRate, double remaining, const CellPopulation& pop)
{
    if (!std::isfinite(totalRate)) {
        throw std::runtime_error(who() + ": total event rate is not finite (gelation?)");
    }
    std::ostringstream os;
    os << who() << ": " << totalRate * remaining
       << " events expected in the rest of the step (limit " << maxExpectedEvents << ", "
       << pop.particles.size() << " particles, volume " << pop.volume
       << "): the kernel or inception rate is far too large for the step, or the "
          "population is past gelation";
    throw std::runtime_error(os.str());
}

template <class Jump>
bool JumpProcess<Jump>::accepted(std::size_t j1, const Particle& p1, std::size_t j2,
                                 const Particle& p2, const CoagulationKernel& kernel, Rng& rng)
{
    // The pair was proposed at the sampler's rate (a majorant); its jump rate is K (w2):
    // accepted with their ratio (thinning)
    const double proposed = sampler_.pairRateAt(j1, j2);
    const double K = kernel(p1.type, p2.type);
    const double target = sampler_.targetRate(K, p2);
    // One uniform for every pair, also where it decides nothing (K (w2) equal to the rate it
    // was proposed at), so that a proposal takes a fixed count of the engine's words and the
    // loop can tell the next proposal's words before this acceptance (events with draws made ahead)
    const double uAccept = rng.uniform();
    // Accepted when target < proposed and uAccept * proposed < target, or when target >=
    // proposed (equal, or above by round-off); the two compares combined without a branch:
    // target < proposed holds for some pairs and not for others at random (values the tree
    // holds exactly or not), and a branch on it was mispredicted in about a tenth of the
    // events (cachegrind's branch simulation, SWA additive at N = 1e5)
    if (target <= proposed * (1.0 + 1e-9)) {
        return static_cast<bool>(int(uAccept * proposed < target) | int(target >= proposed));
    }
    std::ostringstream os;
    os << who() << ": kernel '" << kernel.name() << "' value " << K << " exceeds its majorant "
       << kernel.majorant(p1.type, p2.type) << " at masses " << p1.type.mass << ", "
       << p2.type.mass;
    if (!std::isfinite(K) || !std::isfinite(proposed)) {
        os << " (non-finite values: has the system gelled?)";
        throw std::runtime_error(os.str());
    }
    throw std::logic_error(os.str());
}

template <class Jump>
void JumpProcess<Jump>::advance(CellPopulation& pop, const CoagulationKernel& kernel,
                                double inceptionRate, double dt, Rng& rng,
                                StepStatistics& stats)
{
    checkArguments(pop, inceptionRate, dt);
    if (&kernel != &sampler_.kernel()) sampler_.configure(kernel, who());
    ParticleVector& P = pop.particles;
    const double w = Jump::equalWeights ? commonWeight(P, inceptionRate) : 0.0;

    // Number control on entry (the caller may have moved particles in or out).
    while (control_.maxParticles > 0 && P.size() > control_.maxParticles) {
        halvePopulation(pop, Jump::equalWeights, rng, stats);
    }
    if (closedControl(inceptionRate)) {
        while (!P.empty() && P.size() < control_.minParticles) duplicatePopulation(pop, stats);
    }

    // Room for the expected inceptions, so that no event allocates.
    const std::size_t capacity = expectedCapacity(pop, inceptionRate, dt);
    P.reserve(capacity);
    sampler_.build(P, capacity);

    if (drawsAhead_ && AheadInTwoHalves::pays(sampler_)) {
        events<AheadInTwoHalves>(pop, kernel, inceptionRate, w, dt, rng, stats);
    } else if (drawsAhead_ && AheadInOnePiece::pays(sampler_)) {
        events<AheadInOnePiece>(pop, kernel, inceptionRate, w, dt, rng, stats);
    } else {
        events<NotAhead>(pop, kernel, inceptionRate, w, dt, rng, stats);
    }
}

template <class Jump>
template <class Mode>
void JumpProcess<Jump>::events(CellPopulation& pop, const CoagulationKernel& kernel,
                               double inceptionRate, double w, double dt, Rng& rng,
                               StepStatistics& stats)
{
    ParticleVector& P = pop.particles;
    // Pair rates summed over ordered pairs: SWA K w2 / V (eq 22; w2 inside the sampler's
    // second factors), DSA K w / (2V) (each unordered pair at K w / V, eqs 12, 16-17).
    const double pairFactor = Jump::equalWeights ? 0.5 * w : 1.0;
    const double inceptionPerVolume = inceptionRate / inception_.weight;
    double t = 0.0;

    for (;;) {
        const std::size_t n = P.size();
        const double inceptionRate = inceptionPerVolume * pop.volume;  // eq 10 (DSA), eq 20 (SWA)
        const double scale = pairFactor / pop.volume;
        const double totalRate = inceptionRate + sampler_.rateSum(n) * scale;
        if (!(totalRate > 0.0)) break;
        checkRate(totalRate, dt - t, pop);
        // Exact waiting time of the jump process (Gillespie), rates fixed until the next jump
        t += rng.exponential(totalRate);
        if (!(t <= dt)) break;

        const double u = rng.uniform() * totalRate;
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

        // ---- coagulation: a pair from the majorant, accepted with probability K/Khat (K w2 over
        //      the pair's proposal rate, from the tree's quantised Khat w2)
        //      (j1 == j2 and rejections are fictitious jumps)
        std::size_t j1 = 0;
        std::size_t j2 = 0;
        if (Mode::drawsAhead) {
            sampler_.proposeAhead((u - inceptionRate) / scale, n, rng, P.data(), j1, j2);
            // A later proposal from the engine's words past this pair's acceptance and
            // this event's rates (the mode's wordsToProposal, EventWords)
            Mode::finishEarlier(sampler_, P.data());
            Rng::Engine peek = rng.engine();
            if (j1 != j2 && j1 < n && j2 < n) {
                for (int word = 0; word < EventWords::acceptance; ++word) peek();
            }
            for (int word = 0; word < Mode::wordsToProposal; ++word) peek();
            const double uNext = Rng::toUniform(peek()) * totalRate;  // its choice
            if (uNext >= inceptionRate) {
                Mode::drawAhead(sampler_, (uNext - inceptionRate) / scale, n, peek, P.data());
            }
        } else {
            sampler_.propose((u - inceptionRate) / scale, n, rng, P.data(), j1, j2);
        }
        const bool real =
            j1 != j2 && j1 < n && j2 < n && accepted(j1, P[j1], j2, P[j2], kernel, rng);
        if (!real) {
            ++stats.fictitious;
            continue;
        }
        ++stats.coagulations;
        jump_.coagulate(pop, j1, j2, rng, sampler_);  // the algorithm's jump
        if (closedControl(inceptionRate)) {
            while (!P.empty() && P.size() < control_.minParticles) duplicate(pop, stats);
        }
    }
}

//- The factories of the algorithms (SwaAlgorithm.cpp, DsaAlgorithm.cpp)
std::unique_ptr<CellAlgorithm> makeSwa(const CoagulationKernel&, const InceptionModel&,
                                       const NumberControl&, DrawsAhead);
std::unique_ptr<CellAlgorithm> makeDsa1(const CoagulationKernel&, const InceptionModel&,
                                        const NumberControl&, DrawsAhead);
std::unique_ptr<CellAlgorithm> makeDsa2(const CoagulationKernel&, const InceptionModel&,
                                        const NumberControl&, DrawsAhead);

} // namespace detail
} // namespace coag

#endif
