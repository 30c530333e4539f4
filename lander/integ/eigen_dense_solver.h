#pragma once
// Internal to touchdown_integ (the CVODE wrapper owns every SUNDIALS object): a SUNDIALS dense
// linear solver that factors the Newton matrix with Eigen's partial-pivoting LU.
//
// Why not SUNDIALS' own (SUNLinSol_Dense): its factorisation is a column loop with no blocking or
// vectorisation. On the lander's 42-46 states, measured on this project's machine (2026-12-05,
// -O3 -march=native, a diagonally dominant 46 x 46 matrix), it took 62 us to factor and solve and
// 4.1 us to solve again, Eigen's 8.3 and 0.8 us; the linear algebra was 14 % of a lunar-study
// landing's time. Both are LU with partial pivoting by rows, so they pick the same pivots and differ
// only in the order of their sums (the results agree to rounding, not bit for bit).
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

namespace touchdown::integ {

// A direct solver for SUNDenseMatrix systems of size n: setup factors, solve back-substitutes.
// A zero or non-finite pivot fails the setup as recoverable (SUNLS_LUFACT_FAIL), as SUNDIALS' own
// does, so CVODE retries with a smaller step. Free it with SUNLinSolFree. Nothing allocates after
// construction.
SUNLinearSolver MakeEigenDenseSolver(int n, SUNContext context);

}  // namespace touchdown::integ
