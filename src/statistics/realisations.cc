#include "statistics/realisations.h"

namespace penny
{
  // Each rank packs its rows as (index, length, values...) into one buffer;
  // every rank gathers all buffers (MPI_Allgatherv) and unpacks them by index.
  std::vector<std::vector<double>>
  spread_over_ranks(MPI_Comm communicator, const unsigned int n,
                    const std::function<std::vector<double>(unsigned int)> &piece)
  {
    int rank = 0, size = 1;
    MPI_Comm_rank(communicator, &rank);
    MPI_Comm_size(communicator, &size);

    std::vector<double> packed;
    for (unsigned int index = rank; index < n; index += size)
      {
        const std::vector<double> row = piece(index);
        packed.push_back(index);
        packed.push_back(row.size());
        packed.insert(packed.end(), row.begin(), row.end());
      }

    int              length = packed.size();
    std::vector<int> lengths(size), offsets(size);
    MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, communicator);
    for (int r = 1; r < size; ++r)
      offsets[r] = offsets[r - 1] + lengths[r - 1];
    std::vector<double> all(offsets[size - 1] + lengths[size - 1]);
    MPI_Allgatherv(packed.data(), length, MPI_DOUBLE, all.data(), lengths.data(), offsets.data(), MPI_DOUBLE,
                   communicator);

    std::vector<std::vector<double>> rows;
    rows.resize(n);
    for (std::size_t position = 0; position < all.size();)
      {
        const std::size_t index = all[position], row_length = all[position + 1];
        rows[index].assign(all.begin() + position + 2, all.begin() + position + 2 + row_length);
        position += 2 + row_length;
      }
    return rows;
  }
} // namespace penny
