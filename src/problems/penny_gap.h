// The penny-gap problem (doc/theory.md, sections 1-3): the subsections its
// model and load are read from, the solve-and-measure routine of the scenes
// that solve one gap, and the set-up of the scenes that search over gap radii.
#pragma once

#include "closed_forms/face_load.h"
#include "closed_forms/sneddon_solution.h"
#include "fe/penny_gap_model.h"
#include "input/entries.h"
#include "output/progress.h"
#include "output/result_folder.h"
#include "output/table.h"
#include "searches/gap_family.h"

#include <deal.II/base/timer.h>

#include <ostream>
#include <string>
#include <vector>

namespace penny
{
  // Geometry, Material, Mesh, Finite element and Linear solver. Once read, a
  // gmsh mesh file is read and checked against the geometry, and a model too
  // large for the memory is refused (check_model_size).
  void penny_gap_model_sections(Sections &sections, PennyGapModelParameters &model);

  // Throws InputError, naming the entries that make the model large, if it
  // would not fit in the memory of this run; `more` names further entries
  // that enlarged it (e.g. an adaptive refinement). Collective.
  void check_model_size(const PennyGapModelParameters &model, double cells, const std::string &more = "");

  // The cells of `model`, known before it is built (fe/penny_gap_mesh.h).
  double model_cells(const PennyGapModelParameters &model);

  // Load: the face traction p(r) of the gap of radius geometry.gap_radius
  // (Type, Peak tension P, the parabola's a or R_p, Expression). Once read,
  // the load must be finite on the face, not zero everywhere, and its largest
  // |p| inside [1e-30, 1e30] Pa: the one bound of every load.
  void face_load_section(Sections &sections, LoadParameters &load, const GeometryParameters &geometry);

  // Load, for the adhesionless gap size: the parabola P (1 - r^2/a^2), its
  // 'Peak tension P' and its a or R_p.
  void parabola_section(Sections &sections, LoadParameters &load);

  // J-integral: the outer radii of the rings (units of c), inside the domain.
  void ring_section(Sections &sections, std::vector<double> &ring_radii, const GeometryParameters &geometry);

  // What every penny-gap scene reads: the model and its J-integral rings,
  // and the face load where the scene solves one (`face_load` not null).
  struct PennyGapInput
  {
    PennyGapModelParameters model;
    std::vector<double>     ring_radii;

    void sections(Sections &sections, LoadParameters *face_load = nullptr);
  };

  // What the adhesive searches read besides the model: the summit
  // p = P - r^2/(2 R_p) of the Bueckner parabola (Load: 'Summit radius R_p'
  // and, where `peak_tension` is not null, 'Peak tension P'), and K_Ic
  // (Adhesion) of the model's material.
  struct AdhesiveSummit
  {
    double summit_radius;             // R_p (m^2/Pa)
    double critical_stress_intensity; // K_Ic (Pa m^1/2)

    void sections(Sections &sections, const MaterialParameters &material, double *peak_tension = nullptr);
  };

  // What the scenes that search for adhesive gaps read: the penny gap and the
  // adhesive summit of its material.
  struct AdhesiveGapInput
  {
    PennyGapInput  gap;
    AdhesiveSummit summit;

    void sections(Sections &sections, double *peak_tension = nullptr);
  };

  struct RingResult
  {
    double radius;                         // in units of the model's length (c)
    double energy_release_rate;            // J (J/m^2)
    double stress_intensity_factor;        // |K_I| = sqrt(E' J) (Pa m^1/2)
    double signed_stress_intensity_factor; // from B(u, u_ref), u_ref under unit pressure
  };

  struct PennyGapMeasurement
  {
    std::vector<RingResult> rings;
    ClosedForm              exact_stress_intensity_factor;
    double                  opening_at_centre; // one face (m)
    ClosedForm              exact_opening_at_centre;
    double                  gap_volume; // both faces (m^3)
    ClosedForm              exact_gap_volume;
    unsigned int            n_cells;
    unsigned int            n_dofs;
    double                  relative_residual;  // the larger of the two solves
    double                  condition_estimate; // CG's estimate; 0 for the direct solver
    std::string             solver;
  };

  // The tables of one solved gap: K_I on every ring beside its closed form
  // `exact` (ring radii in units of `ring_unit`), then `summary`, printed with
  // a note where the FE K_I is negative (the faces would interpenetrate) and
  // written as rings.csv and summary.csv. Returns the largest relative error
  // of |K_I| and of the signed K_I over the rings.
  double report_rings(const std::vector<RingResult> &rings, double exact, const std::string &ring_unit,
                      const Table &summary, const ResultFolder &results, std::ostream &log);

  // Solve, J-integrals on the rings (radii in units of c) and closed forms on
  // a model already built (perhaps adaptively refined); the fields go to
  // `fields` unless it is null.
  PennyGapMeasurement measure_penny_gap(PennyGapModel &model, const FaceLoad &load,
                                        const std::vector<double> &ring_radii, dealii::TimerOutput &timer,
                                        const ResultFolder *fields = nullptr);

  // The same on a model built for `model`.
  PennyGapMeasurement solve_penny_gap(const PennyGapModelParameters &model, const LoadParameters &load,
                                      const std::vector<double> &ring_radii, dealii::TimerOutput &timer);

  // What the scenes that search over gap radii share: a timer of the phases,
  // the family of models of the input (J on its last ring), and a progress
  // line as the solves go. Every model lives on one rank; a search of its own
  // shares its models out over all ranks, and a sweep of independent searches
  // gives each rank its share of them (parallel/spread_over_ranks.h), each
  // search on its rank alone. The results do not depend on the number of ranks.
  struct PennyGapSearch
  {
    PennyGapSearch(const PennyGapInput &gap, std::ostream &log);
    PennyGapSearch(const PennyGapSearch &) = delete;

    // The closing rows of a search's summary: the FE solves of all ranks and
    // the phase times (collective).
    void add_cost(Table &summary) const;

    dealii::TimerOutput timer;
    PennyGapFamily      gaps;
    Progress            progress;
  };
} // namespace penny
