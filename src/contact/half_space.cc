#include "contact/half_space.h"

namespace penny
{
  GridField full_contact_pressure(const FourierTransform &transform, const GridField &heights,
                                  const double E_star)
  {
    const auto multiplier =
        transform.tabulate([=](const Wavevector &q) { return std::complex<double>(E_star / 2 * q.norm()); });
    GridField pressure;
    transform.apply(multiplier, heights, pressure);
    return pressure;
  }
} // namespace penny
