#include "lander/integ/eigen_dense_solver.h"

#include <sundials/sundials_nvector.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/LU>
#include <cmath>
#include <new>

namespace touchdown::integ {

namespace {

struct Content {
  explicit Content(int n) : lu(n), rhs(n) {}
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::VectorXd rhs;  // b, copied: permuting a vector onto itself allocates (Eigen's cycle mask)
  sunindextype last_flag = 0;
};

Content& Of(SUNLinearSolver s) { return *static_cast<Content*>(s->content); }

SUNLinearSolver_Type Type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID Id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int Initialize(SUNLinearSolver s) {
  Of(s).last_flag = 0;
  return SUNLS_SUCCESS;
}

int Setup(SUNLinearSolver s, SUNMatrix a) {
  Content& c = Of(s);
  const sunindextype n = SUNDenseMatrix_Columns(a);
  c.lu.compute(Eigen::Map<const Eigen::MatrixXd>(SUNDenseMatrix_Data(a), n, n));
  // PartialPivLU does not stop at a zero pivot; SUNDIALS' dense solver reports the first one (its
  // 1-based column) and CVODE takes a positive flag as recoverable.
  const auto diagonal = c.lu.matrixLU().diagonal();
  c.last_flag = 0;
  for (sunindextype k = 0; k < n; ++k)
    if (!(std::abs(diagonal[k]) > 0.0) || !std::isfinite(diagonal[k])) {
      c.last_flag = k + 1;
      return SUNLS_LUFACT_FAIL;
    }
  return SUNLS_SUCCESS;
}

int Solve(SUNLinearSolver s, SUNMatrix a, N_Vector x, N_Vector b, realtype) {
  Content& c = Of(s);
  const sunindextype n = SUNDenseMatrix_Columns(a);
  Eigen::Map<Eigen::VectorXd> out(N_VGetArrayPointer(x), n);
  c.rhs = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(b), n);  // x and b may be one vector
  out.noalias() = c.lu.permutationP() * c.rhs;
  c.lu.matrixLU().triangularView<Eigen::UnitLower>().solveInPlace(out);
  c.lu.matrixLU().triangularView<Eigen::Upper>().solveInPlace(out);
  c.last_flag = 0;
  return SUNLS_SUCCESS;
}

sunindextype LastFlag(SUNLinearSolver s) { return Of(s).last_flag; }

int Free(SUNLinearSolver s) {
  if (s == nullptr) return SUNLS_SUCCESS;
  delete static_cast<Content*>(s->content);
  s->content = nullptr;
  SUNLinSolFreeEmpty(s);
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver MakeEigenDenseSolver(int n, SUNContext context) {
  SUNLinearSolver s = SUNLinSolNewEmpty(context);
  if (s == nullptr) throw std::bad_alloc();
  s->ops->gettype = Type;
  s->ops->getid = Id;
  s->ops->initialize = Initialize;
  s->ops->setup = Setup;
  s->ops->solve = Solve;
  s->ops->lastflag = LastFlag;
  s->ops->free = Free;
  s->content = new Content(n);
  return s;
}

}  // namespace touchdown::integ
