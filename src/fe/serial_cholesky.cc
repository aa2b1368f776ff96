#include "fe/serial_cholesky.h"

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace penny
{
  using namespace dealii;

  SerialCholesky::SerialCholesky(const Epetra_CrsMatrix &matrix)
      : upper(matrix.NumGlobalRows64(), matrix.NumGlobalRows64())
  {
    const int *global_column = matrix.ColMap().MyGlobalElements();
    upper.reserve(matrix.NumMyNonzeros() / 2 + matrix.NumMyRows());
    std::vector<std::pair<int, double>> row;
    for (int column = 0; column < matrix.NumMyRows(); ++column)
      {
        // One rank: local row i is global row i, which by symmetry is column i.
        Assert(matrix.RowMap().GID(column) == column, ExcInternalError());
        int     n_entries;
        double *values;
        int    *columns;
        matrix.ExtractMyRowView(column, n_entries, values, columns);
        row.clear();
        for (int k = 0; k < n_entries; ++k)
          if (const int i = global_column[columns[k]]; i <= column)
            row.emplace_back(i, values[k]);
        std::sort(row.begin(), row.end());
        upper.startVec(column);
        for (const auto &[i, value] : row)
          upper.insertBack(i, column) = value;
      }
    upper.finalize();
    factors.cholmod().print = 0; // failures are reported in one line: here, and by info()
    // CHOLMOD's errors, checked after each step: Eigen's factorize reads the
    // analysis's factor without checking that CHOLMOD could make it, and
    // reports a failed factorisation as a success. A matrix that is not
    // positive definite is a warning, which info() reports.
    const auto check = [&](const std::string &step) {
      const int status = factors.cholmod().status;
      if (status == CHOLMOD_OUT_OF_MEMORY)
        throw std::bad_alloc();
      if (status == CHOLMOD_TOO_LARGE)
        throw std::runtime_error("solve: CHOLMOD could not " + step +
                                 " the stiffness matrix: its factor is too large for CHOLMOD's indices");
      if (status < CHOLMOD_OK)
        throw std::runtime_error("solve: CHOLMOD could not " + step + " the stiffness matrix (status " +
                                 std::to_string(status) + ")");
    };
    factors.analyzePattern(upper);
    check("analyse");
    factors.factorize(upper);
    check("factorise");
  }
} // namespace penny
