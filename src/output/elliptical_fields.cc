#include "output/elliptical_fields.h"

#include "output/vtu_writer.h"

#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // One VTK_POLY_LINE cell through the points, ASCII XML.
    std::string polyline_vtu(const std::vector<Point<3>> &points, const FrontData &data)
    {
      const std::size_t  n = points.size();
      std::ostringstream vtu;
      vtu.precision(16);
      vtu << "<?xml version=\"1.0\"?>\n"
             "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
             "<UnstructuredGrid>\n"
          << "<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"1\">\n<PointData>\n";
      for (const auto &[name, values] : data)
        {
          vtu << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">";
          for (const double value : values)
            vtu << ' ' << value;
          vtu << "</DataArray>\n";
        }
      vtu << "</PointData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">";
      for (const auto &x : points)
        vtu << ' ' << x[0] << ' ' << x[1] << ' ' << x[2];
      vtu << "</DataArray>\n"
             "</Points>\n"
             "<Cells>\n"
             "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">";
      for (std::size_t i = 0; i < n; ++i)
        vtu << ' ' << i;
      vtu << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\"> " << n
          << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\"> 4</DataArray>\n"
          << "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
      return vtu.str();
    }
  } // namespace

  void write_elliptical_fields(const LinearElasticSystem<Solid> &system,
                               const DisplacementVector         &displacement,
                               const std::vector<Point<3>> &front_points, const FrontData &front_data,
                               const ResultFolder &results)
  {
    VtuPieces<3> data_out;
    data_out.attach_dof_handler(system.get_dof_handler());
    data_out.add_data_vector(displacement, std::vector<std::string>(3, "u"), DataOut<3>::type_dof_data,
                             std::vector<DataComponentInterpretation::DataComponentInterpretation>(
                                 3, DataComponentInterpretation::component_is_part_of_vector));
    DataOutBase::VtkFlags flags;
    flags.write_higher_order_cells = true;
    flags.physical_units           = {{"u", "m"}};
    data_out.build_patches(system.get_mapping()[0], system.degree(), DataOut<3>::curved_inner_cells);
    write_vtu(data_out, "solution", flags, results, system.get_communicator());
    results.write("front.vtu", polyline_vtu(front_points, front_data));
  }
} // namespace penny
