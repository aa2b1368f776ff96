// Fields of the elliptical-gap model for ParaView.
//
//   solution.vtu/.pvd   the quarter model in physical coordinates (m): the
//                       displacement u (a vector, m), on high-order
//                       Lagrange cells of the element's degree drawn through
//                       the model's mapping (the cells along the front curved);
//   front.vtu           the front as a polyline through the reported front
//                       points, with the point data given (K_I FE and exact).
#pragma once

#include "fe/elasticity.h"
#include "fe/linear_elastic_system.h"
#include "output/result_folder.h"

#include <deal.II/base/point.h>

#include <string>
#include <utility>
#include <vector>

namespace penny
{
  using FrontData = std::vector<std::pair<std::string, std::vector<double>>>;

  void write_elliptical_fields(const LinearElasticSystem<Solid>    &system,
                               const DisplacementVector            &displacement,
                               const std::vector<dealii::Point<3>> &front_points, const FrontData &front_data,
                               const ResultFolder &results);
} // namespace penny
