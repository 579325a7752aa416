# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Reference steady-state mass moments of the 1-D coagulation ducts.

Patterson & Wagner, "A stochastic weighted particle method for coagulation-
advection problems", section 3:

* constant kernel K = K0 (section 3.1): closed forms, eqs (39), (41), (43), (45)
  of the moment equations (38), (40), (42), (44);
* additive kernel K = K0 (i + j) (section 3.2): m1 from eq (50), m0, m2, m3 from
  the steady moment equations integrated numerically;
* the normalised standard deviation of M_{n,1} from inception alone, eq (47).

Conventions
-----------
``I`` is the TOTAL monomer inception rate per unit volume and time, i.e.
dm1/dt = I from inception.  The paper writes the constant-kernel rate as 3*I0,
so I = 3*I0 = 3e8 there; for the additive duct I = 1e5.
Moments are m_k(x) = sum_i i^k c_i(x) (mass in monomer units), zero at the inlet
x = 0, advected with the uniform speed u.

Steady moment equations (u dm/dx = ...):

    constant:  m0' = I - K0/2 m0^2          additive:  m0' = I - K0 m0 m1
               m1' = I                                 m1' = I
               m2' = I + K0 m1^2                       m2' = I + 2 K0 m1 m2
               m3' = I + 3 K0 m1 m2                    m3' = I + 3 K0 (m1 m3 + m2^2)

Public functions
----------------
mass_moment(x, I, u)                    m1 = I x/u, eqs (41) and (50)
constant_duct(x, I, K0, u)              closed forms (39)-(45), shape (4,) + x.shape
duct_ode(kernel, x, I, K0, u)           moment ODEs ("constant" or "additive")
additive_duct(x, I, K0, u)              duct_ode("additive", ...) with exact m1
normalised_sd_m1(x, I, V1, u)           sqrt(n var(M_{n,1}))/m1 = sqrt(u/(I V1 x)), eq (47)
profile(kind, x, I, K0, u)              kind in KINDS
cell_edges(centres, x_inlet)            cell faces from 1-D cell centres
cell_average(kind, lo, hi, I, K0, u)    mean of the profile over [lo, hi]
kind_for_kernel(kernel)                 "constant" -> "constantDuct", ...
not_the_papers_duct(attrs)              why samples' attributes describe another case, or None

The references hold for the paper's duct case alone: particles of unit mass incepted at the
rate I (> 0) everywhere, coagulating with the constant or additive kernel of K0 >= 0, nothing
growing, shrinking or lost, advected along x with the uniform speed u.
"""

import numpy as np

from .samples import GROWTH_TOTALS

N_MOMENTS = 4
KINDS = ("constantDuct", "additiveDuct")

_KERNEL_TO_KIND = {
    "constant": "constantDuct",
    "additive": "additiveDuct",
}


def kind_for_kernel(kernel):
    """Analytic reference kind for a solver kernel name, or None."""
    if kernel is None:
        return None
    return _KERNEL_TO_KIND.get(str(kernel).strip().lower())


def not_the_papers_duct(attrs):
    """Why a run whose samples carry the attributes `attrs` (a dict: the moment samples' or a
    size distribution's) is not the paper's duct case that the references assume, or None
    where none of them says so. In this order: a kernel without a reference; no inception
    rate > 0; a K0 not finite and >= 0; growth or shrinking (GROWTH_TOTALS not 0); masses in
    kg (a density with massUnit 1 kg: the incepted particles' mass is then a physical one,
    not the unit of mass). Not in the attributes, so not checked: the inception's mass and
    extent (a zone, a field) and the flow."""
    kernel = attrs.get("kernel")
    if kernel is None:
        return "the samples lack the attribute 'kernel'"
    if kind_for_kernel(kernel) is None:
        return "the kernel is '%s' (the references': constant or additive)" % kernel

    def number(key):
        try:
            return float(attrs[key])
        except (TypeError, ValueError):
            return np.nan

    for key in ("inceptionRate", "K0"):
        if key not in attrs:
            return "the samples lack the attribute '%s'" % key
    rate, K0 = number("inceptionRate"), number("K0")
    if not (np.isfinite(rate) and rate > 0):
        return "the case has no inception (inceptionRate %g)" % rate
    if not (np.isfinite(K0) and K0 >= 0):
        return "the kernel's K0 is %g" % K0
    grown = number("grownMass") if "grownMass" in attrs else 0.0
    if grown != 0:
        return "the case has growth (grown mass %g)" % grown
    lost = {k: number(k) for k in GROWTH_TOTALS[1:] if k in attrs}
    if any(v != 0 for v in lost.values()):
        return "the case loses particles to shrinking (%s)" % ", ".join(
            "%s %g" % kv for kv in lost.items())
    density = number("density") if "density" in attrs else 0.0
    unit = number("massUnit") if "massUnit" in attrs else 1.0
    if density > 0 and unit == 1.0:
        return ("the particles' masses are in kg (density %g kg/m3, massUnit 1 kg), the "
                "references' in units of the incepted particle's mass" % density)
    return None


def mass_moment(x, I, u=1.0):
    """m1(x) = I x/u: mass is advected, coagulation conserves it.

    Eq (41) (constant kernel, I = 3 I0) and eq (50) (any kernel, the steady limit
    of eqs 48-49).  Negative x (upstream of the inlet) gives 0."""
    return I * np.maximum(np.asarray(x, dtype=float), 0.0) / u


def constant_duct(x, I, K0, u=1.0):
    """Closed-form moments of the constant-kernel duct, eqs (39), (41), (43), (45)
    with 3 I0 = I, the solutions of the moment equations (38), (40), (42), (44).

    Returns an array of shape (4,) + shape(x): m0, m1, m2, m3.
    Negative x (upstream of the inlet) gives zeros.
    """
    x = np.maximum(np.asarray(x, dtype=float), 0.0)
    s = x / u  # residence time
    if K0 > 0.0:
        m0 = np.sqrt(2.0 * I / K0) * np.tanh(np.sqrt(I * K0 / 2.0) * s)   # eq (39)
    else:
        m0 = I * s
    m1 = mass_moment(x, I, u)                                             # eq (41)
    m2 = I * s + K0 * I**2 * s**3 / 3.0                                   # eq (43)
    m3 = I * s + K0 * I**2 * s**3 + K0**2 * I**3 * s**5 / 5.0             # eq (45)
    return np.stack([m0, m1, m2, m3])


def _rhs(kernel, I, K0, u):
    kernel = kernel.lower()
    if kernel == "constant":
        def f(_x, m):   # eqs (38), (40), (42), (44)
            m0, m1, m2, m3 = m
            return np.array([I - 0.5 * K0 * m0 * m0,
                             I,
                             I + K0 * m1 * m1,
                             I + 3.0 * K0 * m1 * m2]) / u
    elif kernel == "additive":
        def f(_x, m):   # m1' from eq (48); the others from eq (34) with K = K0 (i + j)
            m0, m1, m2, m3 = m
            return np.array([I - K0 * m0 * m1,
                             I,
                             I + 2.0 * K0 * m1 * m2,
                             I + 3.0 * K0 * (m1 * m3 + m2 * m2)]) / u
    else:
        raise ValueError("no moment ODE for kernel '%s'" % kernel)
    return f


def duct_ode(kernel, x, I, K0, u=1.0, rtol=1e-10):
    """Integrate the steady moment ODEs from m = 0 at x = 0 (scipy solve_ivp).

    kernel: "constant" (eqs 38, 40, 42, 44) or "additive".  Returns shape (4,) + shape(x).
    One integration covers all requested points (any order, repeats allowed).
    """
    from scipy.integrate import solve_ivp

    x = np.asarray(x, dtype=float)
    xc = np.maximum(x.ravel(), 0.0)
    out = np.zeros((N_MOMENTS, xc.size))
    if xc.size == 0:
        return out.reshape((N_MOMENTS,) + x.shape)
    xs, inv = np.unique(xc, return_inverse=True)
    xmax = xs[-1]
    if xmax > 0.0:
        # absolute tolerance far below the smallest scale of interest (m ~ I x/u)
        atol = 1e-6 * rtol * max(abs(I) * xmax / u, 1e-300)
        sol = solve_ivp(_rhs(kernel, I, K0, u), (0.0, xmax), np.zeros(N_MOMENTS),
                        method="DOP853", t_eval=xs, rtol=rtol, atol=atol)
        if not sol.success:
            raise RuntimeError("moment ODE integration failed: " + sol.message)
        vals = sol.y  # (4, len(xs)), xs[0] may be 0 -> zeros
        out = vals[:, inv]
    return out.reshape((N_MOMENTS,) + x.shape)


def additive_duct(x, I, K0, u=1.0, rtol=1e-10):
    """Moments of the additive-kernel duct: m1 = I x/u (eq 50), m0, m2, m3 by ODE."""
    m = duct_ode("additive", x, I, K0, u, rtol=rtol)
    m[1] = mass_moment(x, I, u)
    return m


def normalised_sd_m1(x, I, V1, u=1.0):
    """Normalised standard deviation of M_{n,1} from inception alone, eq (47):

        sqrt(n var(M_{n,1}(x))) / m1(x) = sqrt(u / (I V1 x)),   I = 3 I0,

    x the distance from the inlet (the cell centre).  It holds for both kernels
    (section 3.2: Figure 9 as Figure 4)."""
    return np.sqrt(u / (I * V1 * np.asarray(x, dtype=float)))


def profile(kind, x, I, K0, u=1.0):
    """Point values m_k(x), shape (4,) + shape(x), for kind in KINDS."""
    if kind == "constantDuct":
        return constant_duct(x, I, K0, u)
    if kind == "additiveDuct":
        return additive_duct(x, I, K0, u)
    raise ValueError("unknown analytic reference '%s' (known: %s)" % (kind, ", ".join(KINDS)))


def cell_edges(centres, x_inlet=0.0):
    """Lower and upper faces of 1-D cells from their (sorted or not) centres.

    Inner faces are midpoints between neighbouring distinct centres; the end
    faces are extrapolated by half the neighbouring spacing; the lower face of
    the first cell is not allowed upstream of x_inlet.  Cells sharing a centre
    x (several cells across the duct) get the same faces.
    Returns (lo, hi) arrays in the order of ``centres``.
    """
    c = np.asarray(centres, dtype=float)
    xs, inv = np.unique(c, return_inverse=True)
    if xs.size == 1:
        half = abs(xs[0] - x_inlet)
        lo, hi = np.array([xs[0] - half]), np.array([xs[0] + half])
    else:
        mid = 0.5 * (xs[1:] + xs[:-1])
        lo = np.concatenate([[xs[0] - (mid[0] - xs[0])], mid])
        hi = np.concatenate([mid, [xs[-1] + (xs[-1] - mid[-1])]])
    if x_inlet is not None:
        lo = np.maximum(lo, x_inlet)
    return lo[inv], hi[inv]


def cell_average(kind, lo, hi, I, K0, u=1.0, x_inlet=0.0, nodes=8):
    """Average of the analytic profile over each cell [lo, hi] (Gauss-Legendre).

    x_inlet shifts the profile: m(x - x_inlet).  Returns shape (4, ncells).
    """
    lo = np.asarray(lo, dtype=float).ravel()
    hi = np.asarray(hi, dtype=float).ravel()
    g, w = np.polynomial.legendre.leggauss(nodes)
    half = 0.5 * (hi - lo)
    mid = 0.5 * (hi + lo)
    pts = mid[:, None] + half[:, None] * g[None, :]          # (ncells, nodes)
    vals = profile(kind, pts - x_inlet, I, K0, u)              # (4, ncells, nodes)
    avg = 0.5 * np.einsum("kcn,n->kc", vals, w)
    # degenerate cells: point value
    zero = half <= 0.0
    if np.any(zero):
        avg[:, zero] = profile(kind, mid[zero] - x_inlet, I, K0, u)
    return avg


# ------------------------------------------------------------ size distributions

def smoluchowski_sizes(kernel, t, K, I=0.0, K0=1.0, n0=None, rtol=1e-10):
    """Number densities n_k(t), k = 1..K, of the homogeneous Smoluchowski equation
    with monomer inception at the total rate I (dm1/dt = I) from n(0) = n0 (default:
    no particle), integrated exactly up to the ODE tolerance:

        dn_k/dt = 1/2 sum_{i+j=k} K(i,j) n_i n_j - n_k sum_j K(k,j) n_j + I delta_k1.

    Only sizes below k feed n_k, and the loss sum is closed by the moments:
    constant K = K0: K0 n_k M0; additive K = K0 (i + j): K0 n_k (k M0 + M1); so the K
    equations with M0 (and M1) as extra unknowns are the exact truncation.  On the
    ducts the homogeneous solution at t = x/u is the steady profile (Patterson &
    Wagner, section 3).  t: scalar or array (any order).  Returns [len(t)][K]."""
    from scipy.integrate import solve_ivp

    kernel = kernel.lower()
    if kernel not in ("constant", "additive"):
        raise ValueError("no size distribution for kernel '%s'" % kernel)
    t = np.atleast_1d(np.asarray(t, dtype=float))
    sizes = np.arange(1, K + 1, dtype=float)
    y0 = np.zeros(K + 2)
    if n0 is not None:
        n0 = np.asarray(n0, dtype=float)
        y0[:len(n0)] = n0[:K]
        y0[K] = n0.sum()
        y0[K + 1] = (np.arange(1, len(n0) + 1) * n0).sum()

    if K > 200:         # FFT convolutions, an explicit method (no dense Jacobian)
        from scipy.signal import fftconvolve as convolve
        method = "RK45"
    else:
        convolve, method = np.convolve, "LSODA"

    def rhs(_t, y):
        n, M0, M1 = y[:K], y[K], y[K + 1]
        d = np.zeros_like(y)
        if kernel == "constant":
            conv = convolve(n, n)[:K - 1]              # sizes k = 2..K
            d[1:K] = 0.5 * K0 * conv
            d[:K] -= K0 * n * M0
            d[K] = I - 0.5 * K0 * M0 * M0
        else:
            conv = convolve(sizes * n, n)[:K - 1]      # sum (i + j) n_i n_j / 2
            d[1:K] = K0 * conv
            d[:K] -= K0 * n * (sizes * M0 + M1)
            d[K] = I - K0 * M0 * M1
        d[0] += I
        d[K + 1] = I
        return d

    out = np.zeros((t.size, K))
    ts, inv = np.unique(np.maximum(t, 0.0), return_inverse=True)
    if ts[-1] > 0.0:
        scale = max(I * ts[-1], y0[K], 1e-300)
        sol = solve_ivp(rhs, (0.0, ts[-1]), y0, method=method, t_eval=ts,
                        rtol=max(rtol, 1e-8) if K > 200 else rtol,
                        atol=1e-8 * rtol * scale)
        if not sol.success:
            raise RuntimeError("Smoluchowski integration failed: " + sol.message)
        out = sol.y[:K, inv].T
    else:
        out[:] = y0[:K]
    return out


def golovin(t, K, N0, K0):
    """Exact n_k(t), k = 1..K, for the additive kernel K0 (i + j) from N0 monomers
    without inception (Golovin 1963): with T = 1 - exp(-K0 N0 t),

        n_k = N0 (1 - T) (k T)^(k-1) exp(-k T) / k!.          Returns [len(t)][K]."""
    from scipy.special import gammaln

    t = np.atleast_1d(np.asarray(t, dtype=float))[:, None]
    k = np.arange(1, K + 1, dtype=float)[None, :]
    T = 1.0 - np.exp(-K0 * N0 * t)
    with np.errstate(divide="ignore", invalid="ignore"):
        logs = (k - 1) * np.log(np.where(T > 0, k * T, 1.0)) - k * T - gammaln(k + 1)
        n = N0 * (1.0 - T) * np.exp(logs)
    n = np.where((T == 0) & (k > 1), 0.0, n)
    return n


def duct_sizes(kernel, lo, hi, K, I, K0, u=1.0, x_inlet=0.0, nodes=8):
    """Cell averages over [lo, hi] (x) of the duct's steady n_k(x) = n_k(t = (x -
    x_inlet)/u) of smoluchowski_sizes (Gauss-Legendre).  Returns [cells][K]."""
    lo = np.atleast_1d(np.asarray(lo, dtype=float))
    hi = np.atleast_1d(np.asarray(hi, dtype=float))
    g, w = np.polynomial.legendre.leggauss(nodes)
    pts = 0.5 * (hi + lo)[:, None] + 0.5 * (hi - lo)[:, None] * g[None, :]
    n = smoluchowski_sizes(kernel, np.maximum(pts.ravel() - x_inlet, 0.0) / u, K, I, K0)
    return 0.5 * np.einsum("cnk,n->ck", n.reshape(pts.shape + (K,)), w)
