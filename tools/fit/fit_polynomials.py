#!/usr/bin/env python3
"""Fits the polynomial cores of kutlog's SIMD math kernels (include/kutlog/simd/constants.hpp).

Offline tool, not part of the build: needs python3-mpmath (Debian). Each core is a smooth
function g on an interval, approximated by a Chebyshev fit (near-minimax) of the given degree,
its coefficients rounded to the kernel's precision; the script prints the maximal error of the
rounded polynomial, measured on a dense grid in 60-digit arithmetic. The kernels' ULP bounds
are then measured exhaustively by kutlog-ulp, not taken from here.

    python3 tools/fit/fit_polynomials.py
"""
import struct
import mpmath as mp

mp.mp.dps = 60


def to_float(v):
    return struct.unpack("f", struct.pack("f", float(v)))[0]


def fit(name, g, lo, hi, degree, precision, weight=lambda x: 1):
    poly, _ = mp.chebyfit(g, [lo, hi], degree + 1, error=True)
    poly = list(reversed(poly))  # lowest degree first
    rounded = [to_float(c) if precision == "float" else float(c) for c in poly]
    worst = mp.mpf(0)
    for i in range(2001):
        x = lo + (hi - lo) * mp.mpf(i) / 2000
        value = sum(mp.mpf(c) * x**j for j, c in enumerate(rounded))
        worst = max(worst, abs(value - g(x)) * weight(x) / abs(g(x)))
    print(f"// {name}: degree {degree} on [{float(lo):.6g}, {float(hi):.6g}], "
          f"max relative error {float(worst):.3g} (2^{float(mp.log(worst, 2)):.1f})")
    suffix = "f" if precision == "float" else ""
    fmt = "{:.9e}" if precision == "float" else "{:.17e}"
    print("  " + ", ".join(fmt.format(c) + suffix for c in rounded))


def safe(f, x0):
    """f with its limit at x0 (the fits' functions are removable singularities there)."""
    return lambda x: f(x) if abs(x - x0) > mp.mpf("1e-20") else f(x0 + mp.mpf("1e-25"))


quarter_pi = mp.pi / 4
# float kernels
fit("asin: asin(s) = s + s*z*P(z), z = s^2",
    safe(lambda z: (mp.asin(mp.sqrt(z)) - mp.sqrt(z)) / (z * mp.sqrt(z)), 0), 0, mp.mpf(1) / 4, 5,
    "float")
fit("sin: sin(r) = r + r*u*S(u), u = r^2",
    safe(lambda u: (mp.sin(mp.sqrt(u)) - mp.sqrt(u)) / (u * mp.sqrt(u)), 0), 0, quarter_pi**2, 3,
    "float")
fit("cos: cos(r) = 1 - u/2 + u^2*C(u), u = r^2",
    safe(lambda u: (mp.cos(mp.sqrt(u)) - 1 + u / 2) / u**2, 0), 0, quarter_pi**2, 3, "float")
half_ln2 = mp.log(2) / 2
fit("exp: exp(r) = 1 + r + r^2*E(r)", safe(lambda r: (mp.exp(r) - 1 - r) / r**2, 0), -half_ln2,
    half_ln2, 5, "float")
fit("log: log(1+f) = f - f^2/2 + f^3*L(f)",
    safe(lambda f: (mp.log(1 + f) - f + f**2 / 2) / f**3, 0), mp.sqrt(0.5) - 1, mp.sqrt(2) - 1, 10,
    "float")
# double cores of pow
s_max = (mp.sqrt(2) - 1) / (mp.sqrt(2) + 1)
fit("pow/log: log(m) = 2s + s*z*A(z), s = (m-1)/(m+1), z = s^2",
    safe(lambda z: (2 * mp.atanh(mp.sqrt(z)) - 2 * mp.sqrt(z)) / (z * mp.sqrt(z)), 0), 0,
    s_max**2, 5, "double")
fit("pow/exp: exp(r) = 1 + r + r^2*E(r)", safe(lambda r: (mp.exp(r) - 1 - r) / r**2, 0),
    -half_ln2, half_ln2, 6, "double")
