// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/CellAlgorithm.hpp"
#include "coagulation/SumTree.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace coag {

namespace {

enum class Mode { SWA, DSA1, DSA2 };

//- sum_j w_j m_j: the physical mass a population stands for (per unit sample volume V)
double physicalMass(const std::vector<Particle>& P)
{
    double s = 0.0;
    for (const Particle& p : P) s += p.weight * p.type.mass;
    return s;
}

//- SWA, DSA1 and DSA2 share the majorant/tree machinery; they differ in the pair rate
//  factor (ordered pairs K w2/V versus K w/(2V)) and in the coagulation jump.
//
//  A "column" is one factor of a majorant term: phi_b(z) (first factors) or phi_b(z)*w
//  (second factors; for DSA the common weight w is pulled out of the sums). Columns whose
//  basis function is constant and that carry no varying weight are sampled uniformly and
//  need no tree storage; all others live in the sum tree.
class ParticleCellAlgorithm final : public CellAlgorithm {
public:
    ParticleCellAlgorithm(Mode mode, const CoagulationKernel& kernel,
                          const InceptionModel& inception, const NumberControl& control);

    std::string name() const override
    {
        switch (mode_) {
        case Mode::SWA: return "SWA";
        case Mode::DSA1: return "DSA1";
        case Mode::DSA2: return "DSA2";
        }
        return "";
    }

    void advance(CellPopulation& pop, double dt, Rng& rng, StepStatistics& stats) override;
    std::size_t workspaceBytes() const override { return tree_.memoryBytes(); }

private:
    struct Column {
        int basis = 0;
        bool weighted = false;  // phi * w (SWA second factors)
        bool uniform = false;   // constant phi, no weight: uniform selection, no tree column
        double constant = 0.0;  // phi when uniform
        std::size_t tree = 0;   // tree column when not uniform
    };

    bool dsa() const { return mode_ != Mode::SWA; }

    void fillLeaf(const Particle& p, std::size_t j)
    {
        if (nTreeColumns_ == 0) return;
        kernel_.basis(p.type, phi_.data());
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

    void buildTree(const std::vector<Particle>& particles, std::size_t capacity)
    {
        tree_.reset(nTreeColumns_, std::max<std::size_t>(capacity, particles.size()));
        for (std::size_t j = 0; j < particles.size(); ++j) fillLeaf(particles[j], j);
        tree_.rebuild();
    }

    double columnTotal(const Column& col, std::size_t n) const
    {
        return col.uniform ? col.constant * static_cast<double>(n) : tree_.total(col.tree);
    }

    //- A particle index from a column; `particles` (the population's array) lets the tree
    //  prefetch the candidates' records on large trees
    std::size_t sampleColumn(const Column& col, std::size_t n, Rng& rng,
                             const Particle* particles) const
    {
        if (col.uniform) return static_cast<std::size_t>(rng.uniformIndex(n));
        return tree_.sample(col.tree, rng.uniform() * tree_.total(col.tree), particles,
                            sizeof(Particle));
    }

    void halve(CellPopulation& pop, Rng& rng, StepStatistics& stats);
    void duplicate(CellPopulation& pop, StepStatistics& stats);
    bool closedDsaControl() const
    {
        return dsa() && control_.minParticles > 0 && inception_.rate == 0.0;
    }

    Mode mode_;
    const CoagulationKernel& kernel_;
    InceptionModel inception_;
    NumberControl control_;

    std::vector<Column> columns_;
    std::size_t nTreeColumns_ = 0;
    std::vector<std::size_t> treeBasis_;  // per tree column: its basis function
    std::vector<char> treeWeighted_;      // per tree column: phi * w
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

ParticleCellAlgorithm::ParticleCellAlgorithm(Mode mode, const CoagulationKernel& kernel,
                                             const InceptionModel& inception,
                                             const NumberControl& control)
    : mode_(mode), kernel_(kernel), inception_(inception), control_(control)
{
    const int nb = kernel_.nBasis();
    const std::vector<MajorantTerm>& terms = kernel_.majorantTerms();
    if (nb <= 0 || terms.empty()) {
        throw std::invalid_argument("coag::makeCellAlgorithm: kernel '" + kernel_.name()
                                    + "' has no majorant terms");
    }
    phi_.assign(static_cast<std::size_t>(nb), 0.0);
    kernel_.basis(ParticleType{}, phi_.data());

    auto columnFor = [&](int b, bool weighted) {
        for (std::size_t i = 0; i < columns_.size(); ++i) {
            if (columns_[i].basis == b && columns_[i].weighted == weighted) return i;
        }
        Column col;
        col.basis = b;
        col.weighted = weighted;
        col.uniform = !weighted && kernel_.constantBasis(b);
        col.constant = phi_[static_cast<std::size_t>(b)];
        if (col.uniform && !(col.constant > 0.0 && std::isfinite(col.constant))) {
            throw std::invalid_argument("coag::makeCellAlgorithm: kernel '" + kernel_.name()
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
    };

    for (const MajorantTerm& t : terms) {
        if (t.first < 0 || t.first >= nb || t.second < 0 || t.second >= nb || !(t.coeff > 0.0)
            || !std::isfinite(t.coeff)) {
            throw std::invalid_argument("coag::makeCellAlgorithm: kernel '" + kernel_.name()
                                        + "' has an invalid majorant term (coeff must be > 0, "
                                          "basis indices in [0, nBasis))");
        }
        termCoeff_.push_back(t.coeff);
        termFirst_.push_back(columnFor(t.first, false));
        termSecond_.push_back(columnFor(t.second, !dsa()));
        termFirstBasis_.push_back(static_cast<std::size_t>(t.first));
        termSecondBasis_.push_back(static_cast<std::size_t>(t.second));
    }
    phi2_.assign(phi_.size(), 0.0);
    termRate_.assign(terms.size(), 0.0);
}

void ParticleCellAlgorithm::halve(CellPopulation& pop, Rng& rng, StepStatistics& stats)
{
    std::vector<Particle>& P = pop.particles;
    const std::size_t n = P.size();
    const double massBefore = physicalMass(P);
    std::size_t keep = n / 2;
    if ((n % 2) == 1 && rng.uniform() < 0.5) ++keep;
    // Partial Fisher-Yates: the first `keep` entries become a uniform random subset.
    for (std::size_t i = 0; i < keep; ++i) {
        const std::size_t j = i + static_cast<std::size_t>(rng.uniformIndex(n - i));
        if (j != i) std::swap(P[i], P[j]);
    }
    P.erase(P.begin() + static_cast<std::ptrdiff_t>(keep), P.end());
    if (dsa()) {
        pop.volume *= 0.5;
    } else {
        for (Particle& p : P) p.weight *= 2.0;
    }
    // Unbiased, but not conservative: the change is booked for mass balances
    stats.controlMass += physicalMass(P) - massBefore;
    ++stats.halvings;
    buildTree(P, tree_.capacity());
}

void ParticleCellAlgorithm::duplicate(CellPopulation& pop, StepStatistics& stats)
{
    std::vector<Particle>& P = pop.particles;
    const std::size_t n = P.size();
    const double massBefore = physicalMass(P);
    P.reserve(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        Particle c = P[i];
        c.tag = -1;
        P.push_back(c);
    }
    pop.volume *= 2.0;
    stats.controlMass += physicalMass(P) - massBefore;
    ++stats.doublings;
    buildTree(P, std::max(tree_.capacity(), P.size()));
}

void ParticleCellAlgorithm::advance(CellPopulation& pop, double dt, Rng& rng,
                                    StepStatistics& stats)
{
    if (!(dt >= 0.0) || !std::isfinite(dt)) {
        std::ostringstream os;
        os << "coag::" << name() << "::advance: dt must be finite and >= 0, got " << dt;
        throw std::invalid_argument(os.str());
    }
    if (!(pop.volume > 0.0) || !std::isfinite(pop.volume)) {
        std::ostringstream os;
        os << "coag::" << name() << "::advance: cell volume must be finite and > 0, got "
           << pop.volume;
        throw std::invalid_argument(os.str());
    }
    std::vector<Particle>& P = pop.particles;

    // DSA: the common weight w (pulled out of the tree sums).
    double dsaWeight = inception_.weight;
    if (dsa() && !P.empty()) {
        dsaWeight = P.front().weight;
        if (!(dsaWeight > 0.0) || !std::isfinite(dsaWeight)) {
            throw std::invalid_argument("coag::" + name()
                                        + "::advance: particle weights must be finite and > 0");
        }
        for (const Particle& p : P) {
            if (p.weight != dsaWeight) {
                throw std::invalid_argument("coag::" + name()
                                            + "::advance: DSA requires all particle weights to "
                                              "be equal");
            }
        }
        if (inception_.rate > 0.0 && dsaWeight != inception_.weight) {
            throw std::invalid_argument("coag::" + name()
                                        + "::advance: DSA with inception requires the particle "
                                          "weights to equal the inception weight");
        }
    }

    // Number control on entry (the caller may have moved particles in or out).
    while (control_.maxParticles > 0 && P.size() > control_.maxParticles) {
        halve(pop, rng, stats);
    }
    if (closedDsaControl()) {
        while (!P.empty() && P.size() < control_.minParticles) duplicate(pop, stats);
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
    buildTree(P, capacity);

    // Ordered-pair rates: SWA K w2 / V (w2 inside the second columns), DSA K w / (2V).
    const double pairFactor = dsa() ? 0.5 * dsaWeight : 1.0;
    const std::size_t nTerms = termCoeff_.size();
    double t = 0.0;

    for (;;) {
        const std::size_t n = P.size();
        const double V = pop.volume;
        const double inceptionRate = inceptionPerVolume * V;
        double majorantSum = 0.0;
        if (n >= 2) {
            for (std::size_t k = 0; k < nTerms; ++k) {
                termRate_[k] = termCoeff_[k] * columnTotal(columns_[termFirst_[k]], n)
                               * columnTotal(columns_[termSecond_[k]], n);
                majorantSum += termRate_[k];
            }
        }
        const double scale = pairFactor / V;
        const double coagulationRate = majorantSum * scale;
        const double totalRate = inceptionRate + coagulationRate;
        if (!(totalRate > 0.0)) break;
        if (!std::isfinite(totalRate)) {
            throw std::runtime_error("coag::" + name()
                                     + "::advance: total event rate is not finite (gelation?)");
        }
        if (totalRate * (dt - t) > maxExpectedEvents) {
            std::ostringstream os;
            os << "coag::" << name() << "::advance: " << totalRate * (dt - t)
               << " events expected in the rest of the step (limit " << maxExpectedEvents
               << ", " << n << " particles, volume " << V
               << "): the kernel or inception rate is far too large for the step, or the "
                  "population is past gelation";
            throw std::runtime_error(os.str());
        }
        t += rng.exponential(totalRate);
        if (!(t <= dt)) break;

        double u = rng.uniform() * totalRate;
        if (u < inceptionRate) {
            // ---- inception
            P.push_back(Particle{inception_.type, inception_.weight, -1});
            const std::size_t j = P.size() - 1;
            if (j >= tree_.capacity()) tree_.resizeCapacity(2 * tree_.capacity());
            fillLeaf(P[j], j);
            updateLeaf(j);
            ++stats.inceptions;
            stats.inceptedMass += inception_.weight * inception_.type.mass;
            while (control_.maxParticles > 0 && P.size() > control_.maxParticles) {
                halve(pop, rng, stats);
            }
            continue;
        }

        // ---- coagulation proposal from the majorant
        u = (u - inceptionRate) / scale;
        std::size_t term = nTerms - 1;
        for (std::size_t k = 0; k + 1 < nTerms; ++k) {
            if (u < termRate_[k]) {
                term = k;
                break;
            }
            u -= termRate_[k];
        }
        const Column& first = columns_[termFirst_[term]];
        const Column& second = columns_[termSecond_[term]];
        const std::size_t j1 = sampleColumn(first, n, rng, P.data());
#if defined(__GNUC__)
        __builtin_prefetch(&P[j1 < n ? j1 : 0]);
#endif
        if (nTreeColumns_ > 0) tree_.prefetchPath(j1);
        const std::size_t j2 = sampleColumn(second, n, rng, P.data());
        if (j1 == j2 || j1 >= n || j2 >= n) {
            ++stats.fictitious;
            continue;
        }

        // Acceptance K/Khat. Khat is evaluated from the basis at the two types (the same
        // values the tree holds, without touching the tree's other columns).
        const Particle& p1 = P[j1];
        const Particle& p2 = P[j2];
        kernel_.basis(p1.type, phi_.data());
        kernel_.basis(p2.type, phi2_.data());
        double majorant = 0.0;
        for (std::size_t k = 0; k < nTerms; ++k) {
            majorant += termCoeff_[k] * phi_[termFirstBasis_[k]] * phi2_[termSecondBasis_[k]];
        }
        const double K = kernel_(p1.type, p2.type);
        if (K < majorant) {
            if (!(rng.uniform() * majorant < K)) {
                ++stats.fictitious;
                continue;
            }
        } else if (!(K <= majorant * (1.0 + 1e-9))) {
            std::ostringstream os;
            os << "coag::" << name() << "::advance: kernel '" << kernel_.name() << "' value " << K
               << " exceeds its majorant " << majorant << " at masses " << p1.type.mass << ", "
               << p2.type.mass;
            if (!std::isfinite(K) || !std::isfinite(majorant)) {
                os << " (non-finite values: has the system gelled?)";
                throw std::runtime_error(os.str());
            }
            throw std::logic_error(os.str());
        }

        // ---- accepted coagulation
        ++stats.coagulations;
        const double m1 = P[j1].type.mass;
        const double m2 = P[j2].type.mass;
        const ParticleType merged = P[j1].type + P[j2].type;
        if (!dsa()) {
            Particle& a = P[j1];
            a.weight *= m1 / (m1 + m2);
            a.type = merged;
            fillLeaf(a, j1);
            updateLeaf(j1);
            continue;
        }

        const double p = (mode_ == Mode::DSA1) ? 0.5 : m1 / (m1 + m2);
        const bool keepFirst = rng.uniform() < p;
        const std::size_t s = keepFirst ? j1 : j2;
        const std::size_t r = keepFirst ? j2 : j1;
        P[s].type = merged;
        fillLeaf(P[s], s);
        updateLeaf(s);
        // Remove r: move the last particle into its slot.
        const std::size_t last = n - 1;
        if (r != last) {
            P[r] = P[last];
            for (std::size_t c = 0; c < nTreeColumns_; ++c) tree_.set(r, c, tree_.value(last, c));
            updateLeaf(r);
        }
        for (std::size_t c = 0; c < nTreeColumns_; ++c) tree_.set(last, c, 0.0);
        updateLeaf(last);
        P.pop_back();

        if (closedDsaControl()) {
            while (!P.empty() && P.size() < control_.minParticles) duplicate(pop, stats);
        }
    }
}

} // namespace

std::vector<std::string> cellAlgorithmNames()
{
    return {"SWA", "DSA1", "DSA2"};
}

std::unique_ptr<CellAlgorithm> makeCellAlgorithm(const std::string& name,
                                                 const CoagulationKernel& kernel,
                                                 const InceptionModel& inception,
                                                 const NumberControl& control)
{
    if (!(inception.rate >= 0.0) || !std::isfinite(inception.rate)) {
        std::ostringstream os;
        os << "coag::makeCellAlgorithm: inception rate must be finite and >= 0, got "
           << inception.rate;
        throw std::invalid_argument(os.str());
    }
    if (!(inception.weight > 0.0) || !std::isfinite(inception.weight)) {
        std::ostringstream os;
        os << "coag::makeCellAlgorithm: inception weight must be finite and > 0, got "
           << inception.weight;
        throw std::invalid_argument(os.str());
    }
    if (!(inception.type.mass > 0.0) || !std::isfinite(inception.type.mass)) {
        std::ostringstream os;
        os << "coag::makeCellAlgorithm: incepted particle mass must be finite and > 0, got "
           << inception.type.mass;
        throw std::invalid_argument(os.str());
    }
    if (control.maxParticles > 0 && control.minParticles > 0
        && control.maxParticles < 2 * control.minParticles) {
        std::ostringstream os;
        os << "coag::makeCellAlgorithm: number control needs maxParticles >= 2*minParticles, got "
           << control.maxParticles << " and " << control.minParticles;
        throw std::invalid_argument(os.str());
    }
    if (name == "SWA") return std::make_unique<ParticleCellAlgorithm>(Mode::SWA, kernel, inception, control);
    if (name == "DSA1") return std::make_unique<ParticleCellAlgorithm>(Mode::DSA1, kernel, inception, control);
    if (name == "DSA2") return std::make_unique<ParticleCellAlgorithm>(Mode::DSA2, kernel, inception, control);
    std::ostringstream os;
    os << "coag::makeCellAlgorithm: unknown algorithm '" << name << "'; valid names are:";
    for (const std::string& n : cellAlgorithmNames()) os << ' ' << n;
    throw std::invalid_argument(os.str());
}

} // namespace coag
