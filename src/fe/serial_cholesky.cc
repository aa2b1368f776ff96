#include "fe/serial_cholesky.h"

#include <deal.II/base/exceptions.h>

#include <algorithm>
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
    factors.cholmod().print = 0; // failures are reported through info(), in one line
    factors.compute(upper);
  }
} // namespace penny
