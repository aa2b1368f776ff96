// The sparse Cholesky factors of a stiffness matrix on one MPI rank, the
// direct solver of fe/linear_elastic_system.h there.
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <Epetra_CrsMatrix.h>

namespace penny
{
  // The supernodal Cholesky factorisation of CHOLMOD (through Eigen) of the
  // symmetric positive definite stiffness matrix on one rank. Its upper
  // triangle by columns is, by symmetry, the lower triangle of Epetra's rows.
  struct SerialCholesky
  {
    explicit SerialCholesky(const Epetra_CrsMatrix &matrix);

    Eigen::SparseMatrix<double>                                            upper;
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Upper> factors;
  };
} // namespace penny
