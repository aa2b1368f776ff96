#include "fe/penny_gap_mesh.h"

#include "fe/boundary_ids.h"
#include "fe/tip_graded_mesh.h"
#include "input/input_error.h"

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <gmsh.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // Quadtree of square cells (fe/tip_graded_mesh.h): a coarse grid of width
    // s = c 2^m (the largest such width not above min(R, H)/2, so that the first
    // coarse cell is [0, s]^2 and c falls on one of its dyadic vertices), then
    // every cell nearer to the tip than `grading_distance` of its own widths is
    // split until the tip cells are c/2^levels wide, and every cell over the gap
    // face until it is c/2^(gap face levels) wide: without those, w(0) is 20
    // times less accurate than K_I. Far from the tip cells double in
    // width every few cells: a geometric grading, ratio 2, out to R and H.
    void generate_quadtree(Triangulation<2> &triangulation, const GeometryParameters &physical_geometry,
                           const MeshParameters &mesh)
    {
      // Built on a domain whose part above z0 is compressed along z by the aspect
      // ratio, then stretched back: cells above z0 become that many times
      // taller than wide, while the tip zone keeps square cells.
      const double       ratio = mesh.cell_aspect_ratio;
      const double       z0    = std::min(physical_geometry.gap_radius, physical_geometry.domain_height / 2);
      GeometryParameters geometry = physical_geometry;
      geometry.domain_height      = z0 + (physical_geometry.domain_height - z0) / ratio;
      const double c              = geometry.gap_radius;
      const double s =
          c *
          std::pow(2.,
                   std::floor(std::log2(std::min(geometry.domain_radius, geometry.domain_height) / (2 * c))));
      const double tip_width = c / std::pow(2., mesh.tip_levels);
      make_tip_graded_mesh(triangulation, coarse_steps(geometry.domain_radius, s),
                           coarse_steps(geometry.domain_height, s), crack_tip(geometry),
                           {tip_width, mesh.grading_distance, c / std::pow(2., mesh.gap_face_levels)});

      const double tolerance = 1e-9 * tip_width;
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          {
            const Point<2> x = face->center();
            face->set_boundary_id(x[0] < tolerance   ? boundary_id::symmetry
                                  : x[1] > tolerance ? boundary_id::far
                                  : x[0] < c         ? boundary_id::gap_face
                                                     : boundary_id::ligament);
          }
      if (ratio != 1)
        GridTools::transform(
            [&](const Point<2> &x) { return Point<2>(x[0], x[1] <= z0 ? x[1] : z0 + ratio * (x[1] - z0)); },
            triangulation);
    }

    // Meshes a .geo with gmsh, passing c, R and H as parser numbers (the .geo
    // declares them with DefineConstant), and returns the path of the .msh.
    std::string mesh_geo_file(const std::string &geo_file, const GeometryParameters &geometry)
    {
      const std::string msh_file =
          (std::filesystem::temp_directory_path() / ("penny-" + std::to_string(getpid()) + ".msh")).string();
      // gmsh 4.8 has no parser API: the numbers go in as command-line options.
      std::vector<std::string> arguments = {"gmsh"};
      for (const auto &[name, value] : {std::pair<std::string, double>{"c", geometry.gap_radius},
                                        {"R", geometry.domain_radius},
                                        {"H", geometry.domain_height}})
        {
          std::ostringstream number;
          number.precision(17);
          number << value;
          arguments.insert(arguments.end(), {"-setnumber", name, number.str()});
        }
      std::vector<char *> argv;
      for (auto &argument : arguments)
        argv.push_back(argument.data());
      gmsh::initialize(argv.size(), argv.data(), false);
      try
        {
          gmsh::option::setNumber("General.Verbosity", 1);
          gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
          gmsh::open(geo_file);
          gmsh::model::mesh::generate(2);
          gmsh::write(msh_file);
        }
      catch (...)
        {
          gmsh::finalize();
          throw InputError("Mesh/Mesh file = '" + geo_file + "' could not be meshed by gmsh");
        }
      gmsh::finalize();
      return msh_file;
    }

    void read_gmsh(Triangulation<2> &triangulation, const GeometryParameters &geometry,
                   const MeshParameters &mesh)
    {
      const bool        is_geo   = std::filesystem::path(mesh.mesh_file).extension() == ".geo";
      const std::string msh_file = is_geo ? mesh_geo_file(mesh.mesh_file, geometry) : mesh.mesh_file;
      GridIn<2>         grid_in(triangulation);
      try
        {
          // The stream reader takes boundary ids from the physical tags.
          std::ifstream in(msh_file);
          grid_in.read_msh(in);
        }
      catch (const std::exception &)
        {
          if (is_geo)
            std::filesystem::remove(msh_file);
          throw InputError("Mesh/Mesh file = '" + mesh.mesh_file +
                           "' is not a readable 2D gmsh mesh of quadrilaterals");
        }
      if (is_geo)
        std::filesystem::remove(msh_file);

      std::set<types::boundary_id> ids;
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          ids.insert(face->boundary_id());
      for (const auto id : {boundary_id::symmetry, boundary_id::gap_face, boundary_id::ligament})
        if (ids.count(id) == 0)
          throw InputError("Mesh/Mesh file = '" + mesh.mesh_file + "' lacks physical curve tag " +
                           std::to_string(id) + " (1 axis, 2 gap face, 3 ligament, 4 far boundary)");
    }

  } // namespace

  void make_penny_gap_mesh(Triangulation<2> &triangulation, const GeometryParameters &geometry,
                           const MeshParameters &mesh)
  {
    if (mesh.generator == MeshParameters::Generator::builtin)
      generate_quadtree(triangulation, geometry, mesh);
    else
      {
        read_gmsh(triangulation, geometry, mesh);
        if (!has_vertex_at(triangulation, crack_tip(geometry), 1e-12 * geometry.gap_radius))
          throw InputError("Mesh/Mesh file = '" + mesh.mesh_file +
                           "' has no vertex at the crack tip (c, 0) of Geometry/Gap radius c");
      }
    triangulation.refine_global(mesh.global_refinements);
  }
} // namespace penny
