#include "fourier/grid_resampling.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace penny
{
  namespace
  {
    // MPI_Alltoallv of blocks in rank order: counts[r] values go to (come
    // from) rank r.
    void exchange(const void *sent, const std::vector<int> &send_counts, void *received,
                  const std::vector<int> &receive_counts, const MPI_Datatype type,
                  const MPI_Comm communicator)
    {
      std::vector<int> send_offsets(send_counts.size(), 0), receive_offsets(receive_counts.size(), 0);
      std::partial_sum(send_counts.begin(), send_counts.end() - 1, send_offsets.begin() + 1);
      std::partial_sum(receive_counts.begin(), receive_counts.end() - 1, receive_offsets.begin() + 1);
      MPI_Alltoallv(sent, send_counts.data(), send_offsets.data(), type, received, receive_counts.data(),
                    receive_offsets.data(), type, communicator);
    }
  } // namespace

  GridField resampled(const FourierTransform &from, const FourierTransform &to, const GridField &field)
  {
    const PeriodicGrid &a = from.grid(), &b = to.grid();
    if (a.lx != b.lx || a.ly != b.ly)
      throw std::invalid_argument("resampled: the grids must cover the same rectangle");
    if (from.split() != to.split() || from.n_ranks() != to.n_ranks())
      throw std::invalid_argument("resampled: the grids must be split over the same ranks, or neither");
    const FourierTransform::Spectrum in = from.forward(field);
    FourierTransform::Spectrum       out(to.n_coefficients(), 0.);
    // Integer wavenumbers |kx| < kx_limit, 0 <= ky < ky_limit on both grids.
    const int kx_limit = (std::min(a.nx, b.nx) + 1) / 2, ky_limit = (std::min(a.ny, b.ny) + 1) / 2;
    if (!from.split())
      {
        const unsigned int a_ny = a.ny / 2 + 1, b_ny = b.ny / 2 + 1;
        for (int kx = 1 - kx_limit; kx < kx_limit; ++kx)
          for (int ky = 0; ky < ky_limit; ++ky)
            out[((kx + b.nx) % b.nx) * b_ny + ky] = in[((kx + a.nx) % a.nx) * a_ny + ky];
        return to.inverse(out);
      }

    // Each kept line ky, its 2 kx_limit - 1 kept modes, from its rank on
    // `from` to its rank on `to`; lines travel in increasing ky, so each
    // rank's block arrives in order.
    const int                  kept = 2 * kx_limit - 1;
    std::vector<int>           send_counts(from.n_ranks(), 0), receive_counts(to.n_ranks(), 0);
    FourierTransform::Spectrum sent;
    for (unsigned int ky = from.first_line(); ky < from.first_line() + from.n_lines() && int(ky) < ky_limit;
         ++ky)
      {
        send_counts[to.line_owner(ky)] += kept;
        const std::complex<double> *line = in.data() + std::size_t(ky - from.first_line()) * a.nx;
        for (int kx = 1 - kx_limit; kx < kx_limit; ++kx)
          sent.push_back(line[(kx + a.nx) % a.nx]);
      }
    const unsigned int received_lines =
        std::max(0, std::min<int>(to.first_line() + to.n_lines(), ky_limit) - int(to.first_line()));
    for (unsigned int ky = to.first_line(); ky < to.first_line() + received_lines; ++ky)
      receive_counts[from.line_owner(ky)] += kept;
    FourierTransform::Spectrum received(std::size_t(received_lines) * kept);
    exchange(sent.data(), send_counts, received.data(), receive_counts, MPI_C_DOUBLE_COMPLEX,
             from.communicator());
    for (unsigned int l = 0; l < received_lines; ++l)
      for (int kx = 1 - kx_limit; kx < kx_limit; ++kx)
        out[std::size_t(l) * b.nx + (kx + b.nx) % b.nx] = received[std::size_t(l) * kept + kx + kx_limit - 1];
    return to.inverse(out);
  }

  std::optional<PeriodicGrid> halved(const PeriodicGrid &grid, const unsigned int smallest)
  {
    const auto halvable = [=](const unsigned int n) { return n == 1 || (n % 2 == 0 && n / 2 >= smallest); };
    if (!halvable(grid.nx) || !halvable(grid.ny) || (grid.nx == 1 && grid.ny == 1))
      return std::nullopt;
    return PeriodicGrid{grid.nx == 1 ? 1 : grid.nx / 2, grid.ny == 1 ? 1 : grid.ny / 2, grid.lx, grid.ly};
  }

  GridField interpolated(const FourierTransform &coarse_transform, const GridField &field,
                         const FourierTransform &fine_transform)
  {
    const PeriodicGrid &coarse = coarse_transform.grid(), &fine = fine_transform.grid();
    const unsigned int  sx = fine.nx / coarse.nx, sy = fine.ny / coarse.ny;
    // The coarse rows that fine rows first ... first + n - 1 lie between:
    // from first/sx on, n_needed of them (cyclic; all if that is more).
    const auto needed = [&](const std::pair<unsigned int, unsigned int> &rows) {
      const unsigned int first = rows.first / sx;
      const unsigned int count = rows.second == 0 ? 0 : (rows.first + rows.second - 1) / sx + 2 - first;
      return std::make_pair(first, std::min(count, coarse.nx));
    };
    const auto [first_needed, n_needed] = needed(fine_transform.rows_of(fine_transform.rank()));
    const auto coarse_row = [&](const unsigned int k) { return (first_needed + k) % coarse.nx; };
    std::vector<const double *> rows(n_needed);
    GridField                   received;
    if (!coarse_transform.split())
      for (unsigned int k = 0; k < n_needed; ++k)
        rows[k] = field.data() + std::size_t(coarse_row(k)) * coarse.ny;
    else
      {
        // Every rank knows what every other needs from the fine grid's row blocks.
        std::vector<int> send_counts(coarse_transform.n_ranks(), 0), receive_counts(send_counts);
        GridField        sent;
        for (int r = 0; r < coarse_transform.n_ranks(); ++r)
          {
            const auto [first, count] = needed(fine_transform.rows_of(r));
            for (unsigned int k = 0; k < count; ++k)
              {
                const unsigned int a = (first + k) % coarse.nx;
                if (coarse_transform.row_owner(a) != coarse_transform.rank())
                  continue;
                send_counts[r] += coarse.ny;
                const auto row = field.begin() + std::size_t(a - coarse_transform.first_row()) * coarse.ny;
                sent.insert(sent.end(), row, row + coarse.ny);
              }
          }
        for (unsigned int k = 0; k < n_needed; ++k)
          receive_counts[coarse_transform.row_owner(coarse_row(k))] += coarse.ny;
        received.resize(std::size_t(n_needed) * coarse.ny);
        exchange(sent.data(), send_counts, received.data(), receive_counts, MPI_DOUBLE,
                 coarse_transform.communicator());
        // Each source's rows arrive in the order needed, after those of lower ranks.
        std::vector<std::size_t> next(coarse_transform.n_ranks(), 0);
        std::partial_sum(receive_counts.begin(), receive_counts.end() - 1, next.begin() + 1);
        for (unsigned int k = 0; k < n_needed; ++k)
          {
            std::size_t &offset = next[coarse_transform.row_owner(coarse_row(k))];
            rows[k]             = received.data() + offset;
            offset += coarse.ny;
          }
      }

    GridField result(fine_transform.n_local_points());
    for (unsigned int l = 0; l < fine_transform.n_rows(); ++l)
      for (unsigned int j = 0; j < fine.ny; ++j)
        {
          const unsigned int i = fine_transform.first_row() + l;
          const unsigned int k = i / sx - first_needed, k1 = (k + 1) % n_needed, b = j / sy,
                             b1 = (b + 1) % coarse.ny;
          const double tx = double(i % sx) / sx, ty = double(j % sy) / sy;
          result[std::size_t(l) * fine.ny + j] = (1 - tx) * ((1 - ty) * rows[k][b] + ty * rows[k][b1]) +
                                                 tx * ((1 - ty) * rows[k1][b] + ty * rows[k1][b1]);
        }
    return result;
  }
} // namespace penny
