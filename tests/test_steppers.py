"""Building blocks of the implicit stepper (harness/solver/steppers.py): its tableau's order and its small LU solver."""
from fractions import Fraction

import numpy as np

from harness.infra.jit import python_twin
from harness.solver import steppers
from harness.solver.steppers import SD_A, SD_E, SD_GAMMA


def order_conditions(a, b):
    """sum b, b.c, b.c^2, b.Ac, b.c^3, b.(c Ac), b.A c^2, b.A A c: the Runge-Kutta order conditions up to order 4."""
    c = [sum(row) for row in a]
    a_c = [sum(x * y for x, y in zip(row, c)) for row in a]
    a_c2 = [sum(x * y * y for x, y in zip(row, c)) for row in a]
    a_a_c = [sum(x * y for x, y in zip(row, a_c)) for row in a]

    def dot(u):
        return sum(x * y for x, y in zip(b, u))

    return [sum(b), dot(c), dot([x * x for x in c]), dot(a_c), dot([x ** 3 for x in c]),
            dot([x * y for x, y in zip(c, a_c)]), dot(a_c2), dot(a_a_c)]


def test_sdirk_tableau_is_fourth_order_with_a_third_order_estimate():
    """Hairer & Wanner's SDIRK4 as fractions: b (its last row, stiffly accurate) meets the eight conditions of order
    4 (1, 1/2, 1/3, 1/6, 1/4, 1/8, 1/12, 1/24), the embedded b^ = b - SD_E those of order 3 but not 4, and the
    diagonal is gamma = 1/4."""
    a = [[Fraction(x).limit_denominator(10000) for x in row] for row in SD_A]
    b = a[-1]
    b_hat = [x - Fraction(e).limit_denominator(10000) for x, e in zip(b, SD_E)]
    exact = [Fraction(1), Fraction(1, 2), Fraction(1, 3), Fraction(1, 6), Fraction(1, 4), Fraction(1, 8),
             Fraction(1, 12), Fraction(1, 24)]
    assert order_conditions(a, b) == exact
    assert order_conditions(a, b_hat)[:4] == exact[:4] and order_conditions(a, b_hat)[4:] != exact[4:]
    assert all(a[i][i] == Fraction(SD_GAMMA) for i in range(len(a)))


def test_lu_solver_matches_numpy_with_pivoting():
    """Random 5x5 systems, rows scaled so that partial pivoting swaps at every column: the solution is numpy's
    within round-off times the condition number."""
    lu_factor, lu_solve = python_twin(steppers.lu_factor), python_twin(steppers.lu_solve)
    rng = np.random.default_rng(7)
    for _ in range(200):
        matrix = rng.normal(size=(5, 5)) * np.logspace(-3, 3, 5)[:, None]
        x = rng.normal(size=5)
        rhs = matrix @ x
        factors, pivot = matrix.copy(), np.zeros(5, dtype=np.int64)
        lu_factor(factors, pivot)
        lu_solve(factors, pivot, rhs)
        assert np.abs(rhs - x).max() <= 1e-13 * np.linalg.cond(matrix) * np.abs(x).max()
