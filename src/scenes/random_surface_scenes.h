// Scenes on sampled random surfaces (doc/theory.md, section 7, no FE): summit
// statistics of the full-contact pressure over realisations, the FFT
// boundary-element solver on Westergaard's sinusoid, and the non-contact area
// of random surfaces near full contact beside the layer's laws.
#pragma once

#include "input/parameters.h"
#include "output/result_folder.h"
#include "scenes/scene_support.h"

#include <ostream>

namespace penny
{
  // Sampled moments, summit density and mean summit curvature within
  // 'Largest deviation' standard errors of their lattice expectations.
  Verdict run_summit_statistics_scene(const Parameters &parameters, const ResultFolder &results,
                                      std::ostream &log);

  // The contact half-width at the finest grid within 'Half-width tolerance' of Westergaard's.
  Verdict run_bem_westergaard_scene(const Parameters &parameters, const ResultFolder &results,
                                    std::ostream &log);

  void run_random_contact_scene(const Parameters &parameters, const ResultFolder &results, std::ostream &log);
} // namespace penny
