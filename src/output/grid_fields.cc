#include "output/grid_fields.h"

#include <cstdint>
#include <sstream>
#include <stdexcept>

namespace penny
{
  void write_grid_fields(const std::string &name, const unsigned int nx, const unsigned int ny,
                         const double dx, const double dy, const std::vector<GridFieldOutput> &fields,
                         const ResultFolder &results)
  {
    const std::uint64_t bytes = std::uint64_t(nx) * ny * sizeof(float);
    std::ostringstream  vti;
    vti.precision(17);
    vti << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        << "<ImageData WholeExtent=\"0 " << nx - 1 << " 0 " << ny - 1 << " 0 0\" Origin=\"0 0 0\" Spacing=\""
        << dx << ' ' << dy << " 1\">\n"
        << "<Piece Extent=\"0 " << nx - 1 << " 0 " << ny - 1 << " 0 0\">\n<PointData>\n";
    std::uint64_t offset = 0;
    for (const GridFieldOutput &field : fields)
      {
        if (field.values->size() != std::size_t(nx) * ny)
          throw std::logic_error("write_grid_fields: " + field.name + " does not match the grid");
        vti << "<DataArray type=\"Float32\" Name=\"" << field.name << "\" format=\"appended\" offset=\""
            << offset << "\"/>\n";
        offset += sizeof(std::uint64_t) + bytes;
      }
    vti << "</PointData>\n</Piece>\n</ImageData>\n<AppendedData encoding=\"raw\">\n_";
    // Each array: its size in bytes, then the values with x running fastest
    // (Float32, as deal.II's VTU files: 7 digits are plenty to look at).
    std::vector<float> row_of_x(nx);
    for (const GridFieldOutput &field : fields)
      {
        vti.write(reinterpret_cast<const char *>(&bytes), sizeof bytes);
        for (unsigned int iy = 0; iy < ny; ++iy)
          {
            for (unsigned int ix = 0; ix < nx; ++ix)
              row_of_x[ix] = (*field.values)[std::size_t(ix) * ny + iy];
            vti.write(reinterpret_cast<const char *>(row_of_x.data()), nx * sizeof(float));
          }
      }
    vti << "\n</AppendedData>\n</VTKFile>\n";
    results.write(name + ".vti", vti.str());
    results.write(name + ".pvd", "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
                                 "<Collection>\n<DataSet timestep=\"0\" file=\"" +
                                     name + ".vti\"/>\n</Collection>\n</VTKFile>\n");
  }
} // namespace penny
