// Fields on a periodic grid as a VTK image (.vti) for ParaView: the points
// (ix dx, iy dy), every field as a Float32 point array, raw binary appended
// (little-endian, as the machines penny runs on).
#pragma once

#include "output/result_folder.h"

#include <string>
#include <utility>
#include <vector>

namespace penny
{
  struct GridFieldOutput
  {
    std::string                name;   // with its unit, e.g. "gap (m)"
    const std::vector<double> *values; // nx ny values, index ix ny + iy
  };

  // NAME.vti and NAME.pvd into the results; collective, rank 0's fields count.
  void write_grid_fields(const std::string &name, unsigned int nx, unsigned int ny, double dx, double dy,
                         const std::vector<GridFieldOutput> &fields, const ResultFolder &results);
} // namespace penny
