// Fields of the penny gap and the periodic gap for ParaView, and the penny
// gap's face opening as a table.
//
//   solution.vtu/.pvd       the whole half model in physical coordinates (r, z) (m);
//   solution-tip.vtu/.pvd   the cells within one gap radius of the tip, in the tip
//                           frame ((r - c)/c, z/c): coordinates near the tip are
//                           small numbers, which VTU's Float32 holds to 1e-7
//                           relative, so cells of 1e-9 c stay undistorted;
//   opening.csv             u_z along the gap face beside Sneddon's w(r).
//
// Fields: the displacement u (a vector, m) and its components u_r, u_z, the
// stresses sigma_rr, sigma_zz, sigma_hoop, sigma_rz and von_mises (Pa), and
// the J-integral weight q_weight of one ring. Cells are written as high-order
// Lagrange cells of the element's degree, with units in the VTU metadata.
#pragma once

#include "closed_forms/face_load.h"
#include "fe/elasticity.h"
#include "fe/linear_elastic_system.h"
#include "fracture/crack_extension.h"
#include "output/result_folder.h"

namespace penny
{
  void write_fields(const LinearElasticSystem<Axisymmetric> &system, const DisplacementVector &displacement,
                    const RingExtension<2> &ring, const dealii::Point<2> &tip, const ResultFolder &results);

  // The periodic gap's displacement u (m) as solution.vtu/.pvd in (x, y) (m),
  // high-order Lagrange cells of the element's degree.
  void write_displacement(const LinearElasticSystem<PlaneStrain> &system, const DisplacementVector &displacement,
                          const ResultFolder &results);

  // u_z at the ends and midpoints of the gap-face cells, beside the closed form.
  void write_opening_profile(const LinearElasticSystem<Axisymmetric> &system,
                             const DisplacementVector &displacement, const FaceLoad &load, double gap_radius,
                             double plane_strain_modulus, const ResultFolder &results);
} // namespace penny
