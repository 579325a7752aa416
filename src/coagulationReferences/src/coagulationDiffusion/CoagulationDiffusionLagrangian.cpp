// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulationReferences/coagulationDiffusion/CoagulationDiffusionLagrangian.hpp"
#include "coagulation/random/Normal.hpp"

#include "coagulationReferences/smoluchowski/SmoluchowskiReference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace coag {

namespace {
constexpr double z95 = 1.959963984540054;  // two-sided 95 % normal quantile
constexpr double pi = 3.14159265358979323846;

void checkDim(int dim)
{
    if (dim < 1 || dim > 3) throw std::invalid_argument("dimension must be 1, 2 or 3");
}

//- Per-size running sums of a score and its square.
struct Accumulator {
    explicit Accumulator(std::size_t L) : s(L, 0.0), s2(L, 0.0) {}
    void add(const std::vector<double>& x)
    {
        for (std::size_t l = 0; l < s.size(); ++l) {
            s[l] += x[l];
            s2[l] += x[l] * x[l];
        }
    }
    Estimate result(std::size_t N) const
    {
        Estimate e;
        e.samples = N;
        e.mean.resize(s.size());
        e.halfWidth.resize(s.size());
        const double n = static_cast<double>(N);
        for (std::size_t l = 0; l < s.size(); ++l) {
            const double m = s[l] / n;
            const double var = N > 1 ? std::max(s2[l] / n - m * m, 0.0) * n / (n - 1.0) : 0.0;
            e.mean[l] = m;
            e.halfWidth[l] = z95 * std::sqrt(var / n);
        }
        return e;
    }
    std::vector<double> s, s2;
};
} // namespace

// ---- Box -----------------------------------------------------------------------------------

Box Box::centred(int dim, double R, const double* c)
{
    checkDim(dim);
    Box b;
    b.dim = dim;
    for (int i = 0; i < dim; ++i) {
        const double ci = c ? c[i] : 0.0;
        b.lo[i] = ci - R;
        b.hi[i] = ci + R;
    }
    return b;
}

double Box::volume() const
{
    double v = 1.0;
    for (int i = 0; i < dim; ++i) v *= hi[i] - lo[i];
    return v;
}

bool Box::contains(const double* x) const
{
    for (int i = 0; i < dim; ++i)
        if (x[i] < lo[i] || x[i] > hi[i]) return false;
    return true;
}

void Box::uniform(Rng& rng, double* x) const
{
    for (int i = 0; i < dim; ++i) x[i] = lo[i] + (hi[i] - lo[i]) * rng.uniform();
}

// ---- normals --------------------------------------------------------------------------------

double NormalSource::normal()
{
    if (have_) {
        have_ = false;
        return spare_;
    }
    const double u1 = rng_.uniform();
    const double u2 = rng_.uniform();
    const NormalPair z = boxMuller(u1, u2);
    spare_ = z.second;
    have_ = true;
    return z.first;
}

// ---- the table of (18) ------------------------------------------------------------------------

HomogeneousTable table18(const CoagulationKernel& kernel, std::size_t maxSize, double tauMax,
                         std::size_t storedSizes, std::size_t intervals)
{
    if (storedSizes == 0 || storedSizes > maxSize)
        throw std::invalid_argument("table18: need 1 <= storedSizes <= maxSize");
    HomogeneousTable::Options o;
    o.scaling = HomogeneousTable::Scaling::kernel;   // du/dtau = K(u) (18)
    o.mesh = HomogeneousTable::Mesh::graded;
    o.storedSizes = storedSizes;
    return HomogeneousTable::fromOde(kernel, tauMax, maxSize, intervals, o);
}

// ---- trajectories (8), (16) ------------------------------------------------------------------

void DiffusionProcess::forward(double t0, double t1, double* x, NormalSource& g) const
{
    checkDim(dim);
    const double T = t1 - t0;
    if (T < 0.0) throw std::invalid_argument("DiffusionProcess::forward: t1 < t0");
    if (T == 0.0) return;
    if (!velocity) {
        // v = 0: the exact Gaussian step, variance 2 D T per coordinate (8), (19)
        const double s = std::sqrt(2.0 * D * T);
        for (int i = 0; i < dim; ++i) x[i] += s * g.normal();
        return;
    }
    const std::size_t n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(T / dt)));
    const double h = T / static_cast<double>(n);
    const double s = std::sqrt(2.0 * D * h);
    double v0[3], v1[3], xp[3], dW[3];
    for (std::size_t k = 0; k < n; ++k) {
        const double t = t0 + k * h;
        for (int i = 0; i < dim; ++i) dW[i] = s * g.normal();
        velocity(t, x, v0);
        if (scheme == Scheme::EulerMaruyama) {
            for (int i = 0; i < dim; ++i) x[i] += v0[i] * h + dW[i];  // (8), Euler–Maruyama
            continue;
        }
        for (int i = 0; i < dim; ++i) xp[i] = x[i] + v0[i] * h + dW[i];  // predictor
        velocity(t + h, xp, v1);
        for (int i = 0; i < dim; ++i) x[i] += 0.5 * (v0[i] + v1[i]) * h + dW[i];  // (8), Heun
    }
}

void DiffusionProcess::adjointVelocity(double t, const double* x, double* out) const
{
    if (velocity) velocity(t, x, out);
    else
        for (int i = 0; i < dim; ++i) out[i] = 0.0;
    if (mu && gradMu) {
        double gm[3];
        gradMu(t, x, gm);
        const double m = mu(t, x);
        for (int i = 0; i < dim; ++i) out[i] -= 2.0 * D / m * gm[i];  // v* = v - (2D/mu) grad mu (16)
    }
}

void DiffusionProcess::backward(double t, double* x, NormalSource& g) const
{
    checkDim(dim);
    if (t < 0.0) throw std::invalid_argument("DiffusionProcess::backward: t < 0");
    if (t == 0.0) return;
    if (!velocity && !(mu && gradMu)) {
        const double s = std::sqrt(2.0 * D * t);  // v* = 0: exact Gaussian step back (16), (19)
        for (int i = 0; i < dim; ++i) x[i] += s * g.normal();
        return;
    }
    // (16): X*(tau - h) = X*(tau) - v*(tau, X*) h + sqrt(2D) (W(tau) - W(tau - h)), tau: t -> 0
    const std::size_t n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(t / dt)));
    const double h = t / static_cast<double>(n);
    const double s = std::sqrt(2.0 * D * h);
    double v0[3], v1[3], xp[3], dW[3];
    for (std::size_t k = 0; k < n; ++k) {
        const double tau = t - k * h;
        for (int i = 0; i < dim; ++i) dW[i] = s * g.normal();
        adjointVelocity(tau, x, v0);
        if (scheme == Scheme::EulerMaruyama) {
            for (int i = 0; i < dim; ++i) x[i] += -v0[i] * h + dW[i];
            continue;
        }
        for (int i = 0; i < dim; ++i) xp[i] = x[i] - v0[i] * h + dW[i];
        adjointVelocity(tau - h, xp, v1);
        for (int i = 0; i < dim; ++i) x[i] += -0.5 * (v0[i] + v1[i]) * h + dW[i];
    }
}

// ---- data ------------------------------------------------------------------------------------

double MonodisperseData::value(const double* x) const
{
    if (!support.contains(x)) return 0.0;  // zero outside Omega0 (14)
    return f ? f(x) : n0;
}

// ---- estimators (15)–(17) ----------------------------------------------------------------------

LagrangianEstimator::LagrangianEstimator(const HomogeneousTable& table,
                                         const DiffusionProcess& process,
                                         const MonodisperseData& data)
    : table_(table), process_(process), data_(data)
{
    checkDim(process.dim);
    if (data.support.dim != process.dim)
        throw std::invalid_argument("LagrangianEstimator: support and process dimensions differ");
}

void LagrangianEstimator::scoreRho(double f, double t, double weight,
                                   std::vector<double>& buf) const
{
    table_.solution(f, t, buf.data());
    for (double& b : buf) b *= weight;
}

Estimate LagrangianEstimator::direct(double t, const Box& omega, std::size_t N,
                                     std::uint64_t seed,
                                     const std::function<double(const double*)>& h,
                                     const Density& r) const
{
    if (N == 0) throw std::invalid_argument("direct: N = 0");
    const std::size_t L = table_.sizes();
    const int d = process_.dim;
    const double volume = data_.support.volume();
    NormalSource g(seed);
    Accumulator acc(L);
    std::vector<double> score(L);
    double xi[3] = {0, 0, 0}, X[3] = {0, 0, 0};
    for (std::size_t k = 0; k < N; ++k) {
        if (r.draw) r.draw(g.rng(), xi);
        else data_.support.uniform(g.rng(), xi);  // r uniform in Omega0 by default
        const double rxi = r.pdf ? r.pdf(xi) : 1.0 / volume;
        std::copy(xi, xi + d, X);
        process_.forward(0.0, t, X, g);  // X(t; xi) by (8)
        if (omega.contains(X) && rxi > 0.0) {
            const double w = (h ? h(X) : 1.0) / rxi;  // h(X(t))/r(xi) (15)
            scoreRho(data_.value(xi), t, w, score);  // times rho(t; n0(xi)) (15)
        } else {
            std::fill(score.begin(), score.end(), 0.0);
        }
        acc.add(score);
    }
    return acc.result(N);
}

Estimate LagrangianEstimator::adjoint(double t, const Box& omega, std::size_t N,
                                      std::uint64_t seed,
                                      const std::function<double(const double*)>& h,
                                      const Density& s) const
{
    if (N == 0) throw std::invalid_argument("adjoint: N = 0");
    const std::size_t L = table_.sizes();
    const int d = process_.dim;
    const double volume = omega.volume();
    NormalSource g(seed);
    Accumulator acc(L);
    std::vector<double> score(L);
    double xi[3] = {0, 0, 0}, X[3] = {0, 0, 0};
    for (std::size_t k = 0; k < N; ++k) {
        if (s.draw) s.draw(g.rng(), xi);
        else omega.uniform(g.rng(), xi);  // s uniform in Omega by default
        const double sxi = s.pdf ? s.pdf(xi) : 1.0 / volume;
        std::copy(xi, xi + d, X);
        process_.backward(t, X, g);  // X*(0) by (16), X*(t) = xi
        const double f0 = data_.value(X);  // zero unless x0 in Omega0
        if (f0 > 0.0 && sxi > 0.0) {
            // h(xi)/s(xi) mu(t, xi)/mu(0, x0) rho(t; n0(x0)) (17)
            const double w = (h ? h(xi) : 1.0) / sxi * process_.density(t, xi) /
                             process_.density(0.0, X);
            scoreRho(f0, t, w, score);
        } else {
            std::fill(score.begin(), score.end(), 0.0);
        }
        acc.add(score);
    }
    return acc.result(N);
}

Estimate LagrangianEstimator::adjointPoint(double t, const double* x, std::size_t N,
                                           std::uint64_t seed) const
{
    if (N == 0) throw std::invalid_argument("adjointPoint: N = 0");
    const std::size_t L = table_.sizes();
    const int d = process_.dim;
    NormalSource g(seed);
    Accumulator acc(L);
    std::vector<double> score(L);
    double X[3] = {0, 0, 0};
    for (std::size_t k = 0; k < N; ++k) {
        std::copy(x, x + d, X);
        process_.backward(t, X, g);  // (16) from X*(t) = x
        const double f0 = data_.value(X);
        if (f0 > 0.0) {
            // mu(t, x)/mu(0, x0) rho(t; n0(x0)) (17), the point mass as s
            scoreRho(f0, t, process_.density(t, x) / process_.density(0.0, X), score);
        } else {
            std::fill(score.begin(), score.end(), 0.0);
        }
        acc.add(score);
    }
    return acc.result(N);
}

EffectiveSource LagrangianEstimator::effectiveSource(double t, const double* x, std::size_t N,
                                                     std::uint64_t seed) const
{
    if (process_.velocity)
        throw std::logic_error("effectiveSource: (20) needs v = 0 (Gaussian p)");
    if (N < 2) throw std::invalid_argument("effectiveSource: N < 2");
    const std::size_t L = table_.sizes();
    const int d = process_.dim;
    const double sigma = std::sqrt(2.0 * process_.D * t);  // variance 2Dt (19), (20)
    // B batches of N/B samples: per batch, the unbiased covariances c_ij (1/(n-1)) and
    // F_b = sum K_ij |c_ij| (20); F = mean of the F_b, interval t_{B-1} sd(F_b)/sqrt(B).
    constexpr std::size_t B = 25;
    constexpr double t24 = 2.063898561628021;  // Student t, 24 degrees of freedom, 97.5 %
    const std::size_t nb = N / B;
    if (nb < 2) throw std::invalid_argument("effectiveSource: N < 50");
    NormalSource g(seed);
    const Eigen::MatrixXd& K = table_.kernelMatrix();
    Eigen::MatrixXd R(nb, L);  // rho_l(t; n0(xi_k)) of one batch
    std::vector<double> buf(L);
    double xi[3] = {0, 0, 0};
    double s1 = 0.0, s2 = 0.0;
    for (std::size_t b = 0; b < B; ++b) {
        for (std::size_t k = 0; k < nb; ++k) {
            for (int i = 0; i < d; ++i) xi[i] = x[i] + sigma * g.normal();  // xi ~ N(x, 2Dt) (20)
            table_.solution(data_.value(xi), t, buf.data());
            for (std::size_t l = 0; l < L; ++l) R(k, l) = buf[l];
        }
        const Eigen::RowVectorXd m = R.colwise().mean();
        R.rowwise() -= m;
        // E[rho_i rho_j] - E[rho_i] E[rho_j] (20)
        const Eigen::MatrixXd C = (R.transpose() * R) / (static_cast<double>(nb) - 1.0);
        const double Fb = (K.array() * C.array().abs()).sum();  // (20)
        s1 += Fb;
        s2 += Fb * Fb;
    }
    EffectiveSource out;
    out.samples = nb * B;
    out.F = s1 / B;
    const double var = std::max(s2 / B - out.F * out.F, 0.0) * B / (B - 1.0);
    out.halfWidth = t24 * std::sqrt(var / B);
    return out;
}

// ---- F_R (22)–(23) -------------------------------------------------------------------------------

double gaussianBoxMass(int dim, double R, double D, double t, const double* x)
{
    checkDim(dim);
    const double sigma = std::sqrt(2.0 * D * t);  // sigma = sqrt(2Dt) (23)
    double P = 1.0;
    for (int i = 0; i < dim; ++i) {
        if (sigma == 0.0) {
            P *= std::abs(x[i]) < R ? 1.0 : std::abs(x[i]) == R ? 0.5 : 0.0;
            continue;
        }
        const double a = sigma * std::sqrt(2.0);
        P *= 0.5 * (std::erf((R - x[i]) / a) + std::erf((R + x[i]) / a));  // f_i (23)
    }
    return P;
}

double effectiveSourceBound(int dim, double n0, double C, double R, double D, double t,
                            const double* x)
{
    const double P = gaussianBoxMass(dim, R, D, t, x);
    return 1.5 * n0 * n0 * C * P * (1.0 - P);  // F_R (22)
}

double kernelBoundConstant(const CoagulationKernel& kernel, std::size_t L)
{
    double C = 0.0;
    for (std::size_t i = 1; i <= L; ++i)
        for (std::size_t j = i; j <= L; ++j) {
            ParticleType a, b;
            a.mass = static_cast<double>(i);
            b.mass = static_cast<double>(j);
            C = std::max(C, kernel(a, b) / (static_cast<double>(i) * static_cast<double>(j)));
        }
    return C;  // K_ij <= C i j (2)
}

namespace exact {
namespace {
double Phi(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double phi(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * pi); }
//- antiderivative of Phi(z/sigma)
double Psi(double z, double sigma) { return z * Phi(z / sigma) + sigma * phi(z / sigma); }
} // namespace

double diffusedBoxIntegral(double n0, const Box& support, const Box& omega, double D, double t,
                           const double* v)
{
    checkDim(support.dim);
    if (omega.dim != support.dim) throw std::invalid_argument("diffusedBoxIntegral: dimensions");
    const double sigma = std::sqrt(2.0 * D * t);
    if (sigma == 0.0) throw std::invalid_argument("diffusedBoxIntegral: needs D t > 0");
    double I = n0;
    for (int i = 0; i < support.dim; ++i) {
        const double shift = v ? v[i] * t : 0.0;
        const double c = support.lo[i] + shift, dd = support.hi[i] + shift;
        const double a = omega.lo[i], b = omega.hi[i];
        // int_a^b [Phi((x - c)/sigma) - Phi((x - dd)/sigma)] dx
        I *= Psi(b - c, sigma) - Psi(a - c, sigma) - Psi(b - dd, sigma) + Psi(a - dd, sigma);
    }
    return I;
}

double diffusedBoxDensity(double n0, const Box& support, double D, double t, const double* x,
                          const double* v)
{
    checkDim(support.dim);
    const double sigma = std::sqrt(2.0 * D * t);
    if (sigma == 0.0) throw std::invalid_argument("diffusedBoxDensity: needs D t > 0");
    double P = n0;
    for (int i = 0; i < support.dim; ++i) {
        const double m = x[i] - (v ? v[i] * t : 0.0);
        P *= Phi((support.hi[i] - m) / sigma) - Phi((support.lo[i] - m) / sigma);  // (23)
    }
    return P;
}
} // namespace exact

} // namespace coag
