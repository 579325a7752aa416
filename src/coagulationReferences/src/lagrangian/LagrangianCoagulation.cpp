// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulationReferences/lagrangian/LagrangianCoagulation.hpp"
#include "coagulation/random/CounterStream.hpp"
#include "coagulation/statistics/CorrelatedMean.hpp"  // studentT975

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {

namespace {

constexpr double pi = 3.14159265358979323846;

// Running sums of the scores of one domain
struct Accumulator {
    std::vector<double> s, s2;   // sizes..., total, mass
    std::size_t n = 0, hits = 0;
    explicit Accumulator(std::size_t nSizes) : s(nSizes + 2, 0.0), s2(nSizes + 2, 0.0) {}
    void add(const Score& sc, double weight)
    {
        const std::size_t m = sc.sizes.size();
        ++n;
        if (weight == 0.0) return;
        ++hits;
        for (std::size_t l = 0; l < m; ++l) put(l, weight * sc.sizes[l]);
        put(m, weight * sc.total);
        put(m + 1, weight * sc.mass);
    }
    void addZero() { ++n; }
    void put(std::size_t i, double v)
    {
        s[i] += v;
        s2[i] += v * v;
    }
    IntegralEstimate result() const
    {
        IntegralEstimate e;
        const std::size_t m = s.size() - 2;
        const double N = double(n);
        auto mean = [&](std::size_t i) { return s[i] / N; };
        auto se = [&](std::size_t i) {
            if (n < 2) return 0.0;
            const double var = std::max(0.0, (s2[i] - s[i] * s[i] / N) / (N - 1.0));
            return std::sqrt(var / N);
        };
        e.sizes.resize(m);
        e.sizesSe.resize(m);
        for (std::size_t l = 0; l < m; ++l) {
            e.sizes[l] = mean(l);
            e.sizesSe[l] = se(l);
        }
        e.total = mean(m);
        e.totalSe = se(m);
        e.mass = mean(m + 1);
        e.massSe = se(m + 1);
        e.samples = n;
        e.hits = hits;
        return e;
    }
};

} // namespace

double Sphere::volume() const { return 4.0 / 3.0 * pi * radius * radius * radius; }

bool Sphere::contains(const double x[3]) const
{
    const double dx = x[0] - centre[0], dy = x[1] - centre[1], dz = x[2] - centre[2];
    return dx * dx + dy * dy + dz * dz <= radius * radius;
}

double InitialSource::value(const double x[3]) const
{
    const double dx = x[0] - D.centre[0], dy = x[1] - D.centre[1], dz = x[2] - D.centre[2];
    const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (r > D.radius) return 0.0;
    return profile == Profile::Uniform ? 1.0 : 1.0 - r / D.radius;   // (5.4)
}

LagrangianSolution::LagrangianSolution(const HomogeneousTable& table,
                                       const InitialSource& source, double rate,
                                       std::size_t nSizes)
    : table_(table), source_(source), rate_(rate), nSizes_(nSizes)
{
    if (!(rate > 0.0) || !std::isfinite(rate) || nSizes > table.maxSize() ||
        !(source.D.radius > 0.0)) {
        std::ostringstream os;
        os << "coag::LagrangianSolution: need rate > 0, nSizes <= the table's maxSize ("
           << table.maxSize() << ") and a source radius > 0";
        throw std::invalid_argument(os.str());
    }
}

void LagrangianSolution::homogeneous(double s0, double t, Score& out) const
{
    out.sizes.resize(nSizes_);
    if (s0 <= 0.0) {
        std::fill(out.sizes.begin(), out.sizes.end(), 0.0);
        out.total = out.mass = 0.0;
        return;
    }
    // (2.33): n_l(t) = s0 f_l(s0 K11 t), (4.4)
    table_.evaluate(s0 * rate_ * t, nSizes_, out.sizes.data(), &out.total, &out.mass);
    for (double& v : out.sizes) v *= s0;
    out.total *= s0;
    out.mass *= s0;
}

void LagrangianSolution::fromOrigin(const double x0[3], double t, Score& out) const
{
    homogeneous(source_.value(x0), t, out);
}

Score adjointPoint(const VelocityField& v, const TrajectoryOptions& o, const LagrangianSolution& sol,
                   double t, const double x[3])
{
    double y[3] = {x[0], x[1], x[2]};
    backwardTrajectory(v, o, t, y);   // X*(t, x) (4.2)
    Score s;
    sol.fromOrigin(y, t, s);          // (4.3), (4.4)
    return s;
}

IntegralEstimate adjointIntegral(const VelocityField& v, const TrajectoryOptions& o,
                                 const LagrangianSolution& sol, double t, const Sphere& omega,
                                 std::size_t nPoints, std::uint64_t seed)
{
    CounterStream rng(mix64(seed));
    Accumulator acc(sol.nSizes());
    const double V = omega.volume();   // 1/p(xi) for the uniform density on Omega
    Score sc;
    for (std::size_t i = 0; i < nPoints; ++i) {
        double x[3];
        omega.sample(rng, x);
        backwardTrajectory(v, o, t, x);
        const double s0 = sol.source().value(x);
        if (s0 <= 0.0) {
            acc.addZero();
            continue;
        }
        sol.homogeneous(s0, t, sc);
        acc.add(sc, V);   // E_p n^E(t, xi) / p(xi)
    }
    return acc.result();
}

std::vector<IntegralEstimate> directIntegrals(const VelocityField& v, const TrajectoryOptions& o,
                                              const LagrangianSolution& sol, double t,
                                              const std::vector<Sphere>& omegas,
                                              std::size_t nPoints, std::uint64_t seed)
{
    CounterStream rng(mix64(seed));
    std::vector<Accumulator> acc(omegas.size(), Accumulator(sol.nSizes()));
    const Sphere& D = sol.source().D;
    const double V = D.volume();   // x0 uniform in D = supp S^I
    Score sc;
    for (std::size_t i = 0; i < nPoints; ++i) {
        double x0[3];
        D.sample(rng, x0);
        sol.fromOrigin(x0, t, sc);   // Phi(S^I(x0); t)
        double x[3] = {x0[0], x0[1], x0[2]};
        forwardTrajectory(v, o, 0.0, t, x);   // X(t, x0) (3.2)
        for (std::size_t k = 0; k < omegas.size(); ++k) {
            if (omegas[k].contains(x))   // chi(X(t, x0) in Omega) (3.14)
                acc[k].add(sc, V);
            else
                acc[k].addZero();
        }
    }
    std::vector<IntegralEstimate> out;
    out.reserve(acc.size());
    for (const Accumulator& a : acc) out.push_back(a.result());
    return out;
}

std::vector<PointSourceSample> pointSource(const VelocityField& v, const TrajectoryOptions& o,
                                           const HomogeneousTable& table, double rate,
                                           std::size_t nSizes, const double xStar[3], double T,
                                           const std::function<double(double)>& SP)
{
    if (nSizes > table.maxSize())
        throw std::invalid_argument("coag::pointSource: nSizes > the table's maxSize");
    const std::vector<std::array<double, 3>> path = forwardPath(v, o, T, xStar);   // (4.1)
    const std::size_t M = path.size() - 1;
    std::vector<PointSourceSample> out(M + 1);
    for (std::size_t i = 0; i <= M; ++i) {
        PointSourceSample& p = out[i];
        p.tau = M ? T * double(i) / double(M) : 0.0;
        p.x = path[i];
        const double s = SP(T - p.tau);   // emitted at T - tau_i, coagulated for tau_i
        p.n.sizes.assign(nSizes, 0.0);
        if (s > 0.0) {
            table.evaluate(s * rate * p.tau, nSizes, p.n.sizes.data(), &p.n.total, &p.n.mass);
            for (double& val : p.n.sizes) val *= s;
            p.n.total *= s;
            p.n.mass *= s;
        }
    }
    return out;
}

std::vector<double> SphereFunctionals::flatten() const
{
    std::vector<double> v{In, Ms};
    v.insert(v.end(), In_l.begin(), In_l.end());
    v.insert(v.end(), Sp.begin(), Sp.end());
    return v;
}

SphereFunctionals SphereFunctionals::unflatten(const std::vector<double>& v)
{
    if (v.size() < 2 || v.size() % 2 != 0)
        throw std::invalid_argument("coag::SphereFunctionals::unflatten: bad length");
    SphereFunctionals f;
    const std::size_t n = (v.size() - 2) / 2;
    f.In = v[0];
    f.Ms = v[1];
    f.In_l.assign(v.begin() + 2, v.begin() + 2 + std::ptrdiff_t(n));
    f.Sp.assign(v.begin() + 2 + std::ptrdiff_t(n), v.end());
    return f;
}

SphereFunctionals functionals(const IntegralEstimate& e)
{
    SphereFunctionals f;
    f.In = e.total;                                     // (5.6)
    f.In_l = e.sizes;                                   // (5.5)
    f.Ms = e.total > 0.0 ? e.mass / e.total : 0.0;      // (5.7)
    f.Sp.resize(e.sizes.size());
    for (std::size_t l = 0; l < e.sizes.size(); ++l)   // (5.8)
        f.Sp[l] = e.total > 0.0 ? e.sizes[l] / e.total : 0.0;
    return f;
}

SphereFunctionals deterministicFunctionals(const LagrangianSolution& sol, double t, double r)
{
    // 8-point Gauss-Legendre on [-1, 1]
    static const double xg[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                 -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                 0.7966664774136267,  0.9602898564975363};
    static const double wg[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                 0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                 0.2223810344533745, 0.1012285362903763};
    const Sphere& D = sol.source().D;
    const double b = std::min(r, D.radius);
    IntegralEstimate e;
    e.sizes.assign(sol.nSizes(), 0.0);
    const std::size_t panels = 64;
    const double h = b / double(panels);
    Score sc;
    for (std::size_t p = 0; p < panels; ++p) {
        for (int q = 0; q < 8; ++q) {
            const double rho = h * (double(p) + 0.5 * (xg[q] + 1.0));
            const double x[3] = {D.centre[0] + rho, D.centre[1], D.centre[2]};
            sol.fromOrigin(x, t, sc);   // v = 0: the origin is the point itself (5.3)
            const double w = 0.5 * h * wg[q] * 4.0 * pi * rho * rho;   // shell 4 pi rho^2 drho
            for (std::size_t l = 0; l < e.sizes.size(); ++l) e.sizes[l] += w * sc.sizes[l];
            e.total += w * sc.total;
            e.mass += w * sc.mass;
        }
    }
    return functionals(e);
}

void RealisationStatistics::add(const std::vector<double>& values)
{
    if (n_ == 0) {
        mean_.assign(values.size(), 0.0);
        m2_.assign(values.size(), 0.0);
    } else if (values.size() != mean_.size()) {
        throw std::invalid_argument("coag::RealisationStatistics::add: length changed");
    }
    ++n_;
    for (std::size_t i = 0; i < values.size(); ++i) {   // Welford
        const double d = values[i] - mean_[i];
        mean_[i] += d / double(n_);
        m2_[i] += d * (values[i] - mean_[i]);
    }
}

std::vector<double> RealisationStatistics::mean() const { return mean_; }

std::vector<double> RealisationStatistics::halfWidth95() const
{
    std::vector<double> h(mean_.size(), 0.0);
    if (n_ < 2) return h;
    const double q = studentT975(double(n_ - 1));
    for (std::size_t i = 0; i < h.size(); ++i)
        h[i] = q * std::sqrt(m2_[i] / double(n_ - 1) / double(n_));
    return h;
}

void ExpectationFunctionals::add(const IntegralEstimate& e)
{
    std::vector<double> row{e.total, e.mass};
    row.insert(row.end(), e.sizes.begin(), e.sizes.end());
    if (!rows_.empty() && row.size() != rows_.front().size())
        throw std::invalid_argument("coag::ExpectationFunctionals::add: number of sizes changed");
    rows_.push_back(std::move(row));
}

std::vector<double> ExpectationFunctionals::means() const
{
    if (rows_.empty()) throw std::logic_error("coag::ExpectationFunctionals: no realisation");
    std::vector<double> m(rows_.front().size(), 0.0);
    for (const auto& r : rows_)
        for (std::size_t i = 0; i < m.size(); ++i) m[i] += r[i];
    for (double& x : m) x /= double(rows_.size());
    return m;
}

SphereFunctionals ExpectationFunctionals::mean() const
{
    const std::vector<double> m = means();
    SphereFunctionals f;
    f.In = m[0];
    f.Ms = m[0] > 0.0 ? m[1] / m[0] : 0.0;
    f.In_l.assign(m.begin() + 2, m.end());
    f.Sp.resize(f.In_l.size());
    for (std::size_t l = 0; l < f.Sp.size(); ++l) f.Sp[l] = m[0] > 0.0 ? f.In_l[l] / m[0] : 0.0;
    return f;
}

SphereFunctionals ExpectationFunctionals::halfWidth95() const
{
    const std::vector<double> m = means();
    const std::size_t n = rows_.size(), k = m.size();
    SphereFunctionals h;
    h.In_l.assign(k - 2, 0.0);
    h.Sp.assign(k - 2, 0.0);
    if (n < 2) return h;
    const double q = studentT975(double(n - 1)) / std::sqrt(double(n));
    // sd of a_i - Q b_i (Q = 0: the plain sd of a_i)
    auto sd = [&](std::size_t a, std::size_t b, double Q) {
        double mu = 0.0, s2 = 0.0;
        for (const auto& r : rows_) mu += r[a] - Q * r[b];
        mu /= double(n);
        for (const auto& r : rows_) s2 += (r[a] - Q * r[b] - mu) * (r[a] - Q * r[b] - mu);
        return std::sqrt(s2 / double(n - 1));
    };
    h.In = q * sd(0, 0, 0.0);
    if (m[0] > 0.0) h.Ms = q * sd(1, 0, m[1] / m[0]) / m[0];
    for (std::size_t l = 0; l + 2 < k; ++l) {
        h.In_l[l] = q * sd(l + 2, 0, 0.0);
        if (m[0] > 0.0) h.Sp[l] = q * sd(l + 2, 0, m[l + 2] / m[0]) / m[0];
    }
    return h;
}

} // namespace coag
