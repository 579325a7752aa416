// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulationReferences/smoluchowski/HomogeneousTable.hpp"
#include "coagulationReferences/smoluchowski/NanbuMethod.hpp"
#include "coagulation/random/Rng.hpp"
#include "coagulationReferences/smoluchowski/SmoluchowskiReference.hpp"

#include <algorithm>
#include <memory>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {

namespace {

//- k_ij = K_ij / K_11 (2.32), delegating to the kernel it normalises.
class NormalisedKernel : public CoagulationKernel {
public:
    explicit NormalisedKernel(const CoagulationKernel& k)
        : k_(k), scale_(1.0 / k(ParticleType{1.0}, ParticleType{1.0})), terms_(k.majorantTerms())
    {
        if (!(scale_ > 0.0) || !std::isfinite(scale_))
            throw std::invalid_argument("coag::HomogeneousTable: the normalised scaling needs K_11 > 0");
        for (MajorantTerm& t : terms_) t.coeff *= scale_;
    }
    std::string name() const override { return k_.name() + "/K11"; }
    double operator()(const ParticleType& a, const ParticleType& b) const override
    {
        return scale_ * k_(a, b);
    }
    int nBasis() const override { return k_.nBasis(); }
    void basis(const ParticleType& z, double* phi) const override { k_.basis(z, phi); }
    const std::vector<MajorantTerm>& majorantTerms() const override { return terms_; }
    bool constantBasis(int b) const override { return k_.constantBasis(b); }

private:
    const CoagulationKernel& k_;
    double scale_;
    std::vector<MajorantTerm> terms_;
};

void checkArguments(double sMax, std::size_t maxSize)
{
    if (!(sMax > 0.0) || !std::isfinite(sMax) || maxSize == 0) {
        std::ostringstream os;
        os << "coag::HomogeneousTable: need sMax > 0 and maxSize >= 1, got sMax = " << sMax
           << ", maxSize = " << maxSize;
        throw std::invalid_argument(os.str());
    }
}

// f_1..f_stored, the total and the mass over all sizes of one node into row
void fillRow(const Eigen::VectorXd& f, std::size_t stored, double* row)
{
    const std::size_t L = std::size_t(f.size());
    double total = 0.0, mass = 0.0;
    for (std::size_t l = 0; l < L; ++l) {
        total += f[Eigen::Index(l)];
        mass += double(l + 1) * f[Eigen::Index(l)];
    }
    for (std::size_t l = 0; l < stored; ++l) row[l] = f[Eigen::Index(l)];
    row[stored] = total;
    row[stored + 1] = mass;
}

} // namespace

HomogeneousTable HomogeneousTable::fromOde(const CoagulationKernel& kernel, double sMax,
                                           std::size_t maxSize, std::size_t intervals,
                                           const Options& options)
{
    checkArguments(sMax, maxSize);
    if (intervals == 0)
        throw std::invalid_argument("coag::HomogeneousTable::fromOde: intervals >= 1");
    if (options.storedSizes > maxSize)
        throw std::invalid_argument("coag::HomogeneousTable::fromOde: storedSizes > maxSize");
    HomogeneousTable t;
    t.L_ = maxSize;
    t.stored_ = options.storedSizes > 0 ? options.storedSizes : maxSize;
    t.K_ = coag::kernelMatrix(kernel, t.stored_);
    std::unique_ptr<NormalisedKernel> normalised;
    if (options.scaling == Scaling::normalised) {
        normalised = std::make_unique<NormalisedKernel>(kernel);   // k = K / K_11 (2.32)
        t.timeScale_ = kernel(ParticleType{1.0}, ParticleType{1.0});
    }
    DiscreteSmoluchowski ode(normalised ? *normalised : kernel, maxSize);   // truncated at maxSize
    ode.setTolerances(options.relTol, options.absTol);

    const std::size_t W = t.stored_ + 2, M = intervals + 1;
    t.s_.resize(M);
    t.F_.assign(M * W, 0.0);
    t.dF_.assign(M * W, 0.0);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(Eigen::Index(maxSize));
    f[0] = 1.0;   // f_1(0) = 1 (2.32), u_l(0) = delta_1l (18)
    for (std::size_t m = 0; m < M; ++m) {
        const double r = double(m) / double(intervals);
        const double s =
            options.mesh == Mesh::graded ? sMax * r * r : sMax * double(m) / double(intervals);
        if (m > 0) f = ode.integrate(f, t.s_[m - 1], s);
        t.s_[m] = s;
        fillRow(f, t.stored_, &t.F_[m * W]);
        fillRow(ode.rhs(f), t.stored_, &t.dF_[m * W]);   // df/ds at the node, from the equation
    }
    return t;
}

HomogeneousTable HomogeneousTable::fromOde(const CoagulationKernel& kernel, double sMax,
                                           std::size_t maxSize, std::size_t intervals)
{
    return fromOde(kernel, sMax, maxSize, intervals, Options());
}

HomogeneousTable HomogeneousTable::fromNanbu(const CoagulationKernel& kernel, double sMax,
                                             std::size_t maxSize, std::int64_t N, double alpha,
                                             std::uint64_t seed)
{
    checkArguments(sMax, maxSize);
    if (N <= 0) throw std::invalid_argument("coag::HomogeneousTable::fromNanbu: N >= 1");
    const NormalisedKernel k(kernel);
    NanbuParameters p;
    p.alpha = alpha;
    p.maxSize = maxSize;
    NanbuSmoluchowski nanbu(k, std::vector<std::int64_t>{N}, double(N), p);   // (2.24)
    Rng rng(seed);

    HomogeneousTable t;
    t.L_ = maxSize;
    t.stored_ = maxSize;
    t.timeScale_ = kernel(ParticleType{1.0}, ParticleType{1.0});
    t.K_ = coag::kernelMatrix(kernel, t.stored_);
    const std::size_t W = maxSize + 2;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(Eigen::Index(maxSize));
    auto record = [&]() {
        for (std::size_t l = 1; l <= maxSize; ++l) f[Eigen::Index(l - 1)] = nanbu.density(l);
        t.s_.push_back(nanbu.time());
        t.F_.resize(t.s_.size() * W);
        fillRow(f, maxSize, &t.F_[(t.s_.size() - 1) * W]);
    };
    record();
    while (nanbu.time() < sMax) {
        nanbu.step(rng);
        record();
    }
    return t;
}

std::size_t HomogeneousTable::locate(double s) const
{
    // sMax itself with a relative tolerance of 1e-12 (a time computed as sMax by another route)
    if (!(s >= 0.0 && s <= s_.back() * (1.0 + 1e-12))) {
        std::ostringstream os;
        os << "coag::HomogeneousTable: scaled time " << s << " outside [0, " << s_.back() << "]";
        throw std::out_of_range(os.str());
    }
    const std::size_t m = std::size_t(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin());
    return std::min(m == 0 ? 0 : m - 1, s_.size() - 2);
}

void HomogeneousTable::evaluate(double s, std::size_t n, double* f, double* total,
                                double* mass) const
{
    if (n > stored_) throw std::invalid_argument("coag::HomogeneousTable: size not kept");
    const std::size_t W = stored_ + 2;
    if (s_.size() == 1) {   // cannot happen for sMax > 0; kept for safety
        for (std::size_t l = 0; l < n; ++l) f[l] = F_[l];
        if (total) *total = F_[stored_];
        if (mass) *mass = F_[stored_ + 1];
        return;
    }
    const std::size_t m = locate(s);
    const double h = s_[m + 1] - s_[m];
    const double u = std::min(std::max((s - s_[m]) / h, 0.0), 1.0);
    const double* a = &F_[m * W];
    const double* b = &F_[(m + 1) * W];
    auto value = [&](std::size_t i) {
        if (dF_.empty()) return (1.0 - u) * a[i] + u * b[i];
        // cubic Hermite on [s_m, s_m+1] with the derivatives of the equation at the nodes
        const double* da = &dF_[m * W];
        const double* db = &dF_[(m + 1) * W];
        const double u2 = u * u, u3 = u2 * u;
        const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
        const double h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
        return h00 * a[i] + h10 * h * da[i] + h01 * b[i] + h11 * h * db[i];
    };
    // f >= 0: the cubic can dip below near s = 0, where f_l ~ s^(l-1)
    for (std::size_t l = 0; l < n; ++l) f[l] = std::max(0.0, value(l));
    if (total) *total = value(stored_);
    if (mass) *mass = value(stored_ + 1);
}

double HomogeneousTable::density(std::size_t l, double s) const
{
    if (l == 0 || l > L_) {
        locate(s);
        return 0.0;
    }
    if (l > stored_) throw std::out_of_range("coag::HomogeneousTable: size not kept");
    std::vector<double> f(l);
    evaluate(s, l, f.data(), nullptr, nullptr);
    return f[l - 1];
}

double HomogeneousTable::total(double s) const
{
    double v = 0.0;
    evaluate(s, 0, nullptr, &v, nullptr);
    return v;
}

double HomogeneousTable::mass(double s) const
{
    double v = 0.0;
    evaluate(s, 0, nullptr, nullptr, &v);
    return v;
}

void HomogeneousTable::solution(double n, double t, double* out) const
{
    if (n <= 0.0) {
        std::fill(out, out + stored_, 0.0);
        return;
    }
    evaluate(timeScale_ * n * t, stored_, out, nullptr, nullptr);   // (2.33), (18)
    for (std::size_t l = 0; l < stored_; ++l) out[l] *= n;
}

} // namespace coag
