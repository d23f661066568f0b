"""Jacobi elliptic functions a hair from m = 1 (complementary modulus kc below 2^-200, mc = kc^2 down to the
subnormals), where the closed-form free body lands for moments spanning many orders near the separatrix:
against mpmath at 400 digits (the parameter 1 - mc is not a double there)."""

import mpmath as mp
import numpy as np
import pytest

import rigiddyn

EPS = np.finfo(float).eps


@pytest.mark.parametrize("mc", [1e-130, 1e-300, 1e-320])
def test_jacobi_ellipj_at_tiny_mc_matches_mpmath(mc):
    K = rigiddyn.ellipk(1.0, mc)
    with mp.workdps(400):
        m = 1 - mp.mpf(mc)  # the exact parameter whose complement is the double mc
        for fraction in (0.3, 0.5, 0.6, 0.7, 1.3, -2.6):
            u = fraction * K
            sn, cn, dn = rigiddyn.jacobi_ellipj(u, 1.0, mc)
            ref = [mp.ellipfun(f, mp.mpf(u), m) for f in ("sn", "cn", "dn")]
            # away from their zeros, cn and dn (both ~ sech u, or kc cosh of the rest past K/2) have
            # relative slopes <= 1: the argument's rounding eps |u|, the reduction's eps K and a few ulps
            tol = 8 * EPS * max(1.0, abs(u))
            assert abs(sn - float(ref[0])) <= tol, (fraction, sn, ref[0])
            assert abs(cn / ref[1] - 1) <= tol, (fraction, cn, ref[1])
            assert abs(dn / ref[2] - 1) <= tol, (fraction, dn, ref[2])
