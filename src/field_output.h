// VTU output for ParaView: the displacement as a vector, the four stress
// components, the von Mises stress and the J-integral weight q of one ring,
// with a PVD record that lists the file.
#pragma once

#include "j_integral.h"
#include "penny_gap_model.h"

#include <filesystem>

namespace penny
{
  void write_fields(const PennyGapModel          &model,
                    const DisplacementVector     &displacement,
                    const RingWeight             &ring,
                    const std::filesystem::path  &directory);
} // namespace penny
