#include "parallel/spread_over_ranks.h"

#include "parallel/collective.h"

#include <cstdlib>

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

    // The counter of drawn indices, in a one-sided window on rank 0.
    MPI_Win       window;
    unsigned int *counter = nullptr;
    MPI_Win_allocate(rank == 0 ? sizeof(unsigned int) : 0, sizeof(unsigned int), MPI_INFO_NULL, communicator,
                     &counter, &window);
    if (rank == 0)
      {
        MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, window);
        *counter = 0;
        MPI_Win_unlock(0, window);
      }
    MPI_Barrier(communicator);
    const auto draw = [&]() {
      const unsigned int one = 1;
      unsigned int       index;
      MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, window);
      MPI_Fetch_and_op(&one, &index, MPI_UNSIGNED, 0, 0, MPI_SUM, window);
      MPI_Win_unlock(0, window);
      return index;
    };

    // A piece that throws ends the drawing on every rank (n added to the
    // counter: the same operation as the draws, as concurrent atomic updates
    // of one location must be), and its error is thrown on all of them together.
    std::vector<double> packed;
    std::exception_ptr  failure;
    for (unsigned int index = draw(); index < n; index = draw())
      try
        {
          const std::vector<double> row = piece(index);
          packed.push_back(index);
          packed.push_back(row.size());
          packed.insert(packed.end(), row.begin(), row.end());
        }
      catch (...)
        {
          failure = std::current_exception();
          unsigned int drawn;
          MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, window);
          MPI_Fetch_and_op(&n, &drawn, MPI_UNSIGNED, 0, 0, MPI_SUM, window);
          MPI_Win_unlock(0, window);
          break;
        }

    MPI_Win_free(&window);
    throw_on_every_rank(communicator, failure);

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

  unsigned int ranks_on_this_machine()
  {
    for (const char *name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"})
      if (const char *value = std::getenv(name))
        if (const long ranks = std::strtol(value, nullptr, 10); ranks > 0)
          return ranks;
    return 1;
  }
} // namespace penny
