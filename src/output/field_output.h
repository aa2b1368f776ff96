// VTU output of the penny gap for ParaView: the displacement as a vector, the
// four stress components, the von Mises stress and the J-integral weight q of
// one ring, with a PVD record that lists the file.
#pragma once

#include "fe/elasticity.h"
#include "fe/linear_elastic_system.h"
#include "fracture/crack_extension.h"
#include "output/result_folder.h"

namespace penny
{
  void write_fields(const LinearElasticSystem<Axisymmetric> &system,
                    const DisplacementVector                &displacement,
                    const RingExtension<2>                  &ring,
                    const ResultFolder                      &results);
} // namespace penny
