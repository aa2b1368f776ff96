// ContactEngineering's NetCDF topography (SurfaceTopography's NC format): a
// variable `heights(x, y)` (y the fast index, as a GridField; heights(y, x)
// is transposed), variables `x`
// and `y` whose attribute `length` is the physical size along them, a length
// unit in the attribute `unit` (or `length_unit`) of `x` and of `heights`
// ("m" when absent), and an optional variable `mask(x, y)` whose non-zero
// points are not measured.
#include "input/input_error.h"
#include "topography/topography_formats.h"

#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

namespace penny
{
  namespace
  {
    struct NetcdfFile
    {
      std::string filename;
      int         id = -1;

      ~NetcdfFile()
      {
        if (id >= 0)
          nc_close(id);
      }

      void check(const int status, const std::string &what) const
      {
        if (status != NC_NOERR)
          bad_file(filename, what + ": " + nc_strerror(status));
      }

      int variable(const std::string &name) const
      {
        int variable_id;
        check(nc_inq_varid(id, name.c_str(), &variable_id), "no variable " + in_quotes(name));
        return variable_id;
      }

      bool has_variable(const std::string &name) const
      {
        int variable_id;
        return nc_inq_varid(id, name.c_str(), &variable_id) == NC_NOERR;
      }

      // A text attribute of a variable, or `fallback` when it has none.
      std::string text(const int variable_id, const char *name, const std::string &fallback) const
      {
        nc_type type;
        size_t  length;
        if (nc_inq_att(id, variable_id, name, &type, &length) != NC_NOERR)
          return fallback;
        if (type != NC_CHAR)
          bad_file(filename, std::string("the attribute '") + name + "' is not text");
        std::string value(length, '\0');
        check(nc_get_att_text(id, variable_id, name, value.data()),
              std::string("the attribute '") + name + "'");
        value.erase(value.find_last_not_of('\0') + 1);
        return value;
      }
    };

    // The bytes a classic NetCDF file (CDF-1, -2, -5) must hold: the end of its
    // last fixed-size variable, from the header's "begin" and shape of each
    // (the NetCDF classic format specification). libnetcdf reads zeros past
    // the end of a truncated classic file without an error; the caller
    // compares this with the file's size. 0 for other formats (NetCDF-4
    // files are HDF5, which finds truncation itself).
    std::uintmax_t classic_data_end(const std::string &filename)
    {
      std::ifstream in(filename, std::ios::binary);
      char          magic[4] = {};
      in.read(magic, 4);
      if (!in || std::string(magic, 3) != "CDF")
        return 0;
      const int  version = magic[3];
      const auto number  = [&](const int bytes) {
        std::uint64_t value = 0;
        for (int k = 0; k < bytes; ++k)
          value = value << 8 | static_cast<unsigned char>(in.get());
        if (!in)
          bad_file(filename, "its NetCDF header is cut short");
        return value;
      };
      const int  size_bytes = version == 5 ? 8 : 4;
      const auto skip = [&](const std::uint64_t bytes) { in.seekg((bytes + 3) / 4 * 4, std::ios::cur); };
      const auto name = [&] { skip(number(size_bytes)); };
      const std::uint64_t type_sizes[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
      const auto          type_size    = [&](const std::uint64_t type) {
        if (type == 0 || type > 11)
          bad_file(filename, "its NetCDF header names an unknown type " + std::to_string(type));
        return type_sizes[type];
      };
      const auto attributes = [&] {
        number(4);
        for (std::uint64_t n = number(size_bytes); n > 0; --n)
          {
            name();
            const std::uint64_t size = type_size(number(4));
            skip(number(size_bytes) * size);
          }
      };
      const std::uint64_t records = number(size_bytes);
      // Streaming files leave the record count open.
      const bool                 counted = records != (version == 5 ? ~std::uint64_t(0) : 0xffffffffu);
      std::vector<std::uint64_t> dimensions;
      number(4);
      for (std::uint64_t n = number(size_bytes); n > 0; --n)
        {
          name();
          dimensions.push_back(number(size_bytes));
        }
      attributes();
      // Fixed-size variables end at begin + their bytes; a record variable's
      // last record at begin + (records - 1) record sizes + its bytes per
      // record (the record size the sum of the record variables' padded
      // sizes, or the one variable's bytes unpadded).
      struct Record
      {
        std::uint64_t begin, bytes, padded;
      };
      std::vector<Record> record_variables;
      std::uintmax_t      end = 0;
      number(4);
      for (std::uint64_t n = number(size_bytes); n > 0; --n)
        {
          name();
          std::uint64_t points = 1;
          bool          record = false;
          for (std::uint64_t d = number(size_bytes); d > 0; --d)
            {
              const std::uint64_t id = number(size_bytes);
              if (id >= dimensions.size())
                bad_file(filename, "its NetCDF header names a dimension it does not define");
              if (dimensions[id] == 0) // the unlimited dimension: stored by records
                record = true;
              else
                points *= dimensions[id];
            }
          attributes();
          const std::uint64_t bytes  = points * type_size(number(4));
          const std::uint64_t padded = number(size_bytes);
          const std::uint64_t begin  = number(version == 1 ? 4 : 8);
          if (record)
            record_variables.push_back({begin, bytes, padded});
          else
            end = std::max<std::uintmax_t>(end, begin + bytes);
        }
      std::uint64_t record_size = 0;
      for (const Record &variable : record_variables)
        record_size += record_variables.size() == 1 ? variable.bytes : variable.padded;
      if (counted && records > 0)
        for (const Record &variable : record_variables)
          end = std::max<std::uintmax_t>(end, variable.begin + (records - 1) * record_size + variable.bytes);
      return end;
    }

    double metres_in(const NetcdfFile &file, const std::string &unit)
    {
      try
        {
          return metres_per(unit);
        }
      catch (const InputError &error)
        {
          bad_file(file.filename, error.what());
        }
    }
  } // namespace

  Topography read_netcdf(const std::string &filename)
  {
    NetcdfFile file{filename};
    // A classic file's header is checked against its size before libnetcdf
    // reads it (a damaged header can claim gigabytes).
    if (const std::uintmax_t end = classic_data_end(filename); std::filesystem::file_size(filename) < end)
      bad_file(filename,
               "is truncated or its header damaged: " + std::to_string(std::filesystem::file_size(filename)) +
                   " bytes, its header places data up to byte " + std::to_string(end));
    file.check(nc_open(filename.c_str(), NC_NOWRITE, &file.id), "is not a readable NetCDF file");
    const int heights = file.variable("heights");
    int       n_dimensions;
    file.check(nc_inq_varndims(file.id, heights, &n_dimensions), "the variable 'heights'");
    if (n_dimensions != 2)
      bad_file(filename, "the variable 'heights' has " + std::to_string(n_dimensions) +
                             " dimensions (a height map has two, x and y)");
    int dimensions[2];
    file.check(nc_inq_vardimid(file.id, heights, dimensions), "the variable 'heights'");
    size_t n[2];
    char   names[2][NC_MAX_NAME + 1];
    for (int k = 0; k < 2; ++k)
      {
        file.check(nc_inq_dimlen(file.id, dimensions[k], &n[k]), "the dimensions of 'heights'");
        file.check(nc_inq_dimname(file.id, dimensions[k], names[k]), "the dimensions of 'heights'");
      }
    // heights(y, x): stored with x the fast index, transposed below.
    const bool transposed = std::string(names[0]) == "y" && std::string(names[1]) == "x";
    if (transposed)
      std::swap(n[0], n[1]);

    // The physical size along each axis: the attribute `length` of the variable x or y.
    double      lengths[2];
    std::string lateral_unit = "m";
    for (int k = 0; k < 2; ++k)
      {
        const std::string axis = k == 0 ? "x" : "y";
        if (!file.has_variable(axis))
          bad_file(filename, "has no variable " + in_quotes(axis) + " stating the length along it");
        const int id = file.variable(axis);
        size_t    values;
        file.check(nc_inq_attlen(file.id, id, "length", &values),
                   "the variable " + in_quotes(axis) + " states no attribute 'length'");
        if (values != 1)
          bad_file(filename, "the attribute 'length' of " + in_quotes(axis) + " holds " +
                                 std::to_string(values) + " values, not one");
        file.check(nc_get_att_double(file.id, id, "length", &lengths[k]),
                   "the attribute 'length' of " + in_quotes(axis));
        lateral_unit = file.text(id, "unit", file.text(id, "length_unit", lateral_unit));
      }
    const std::string height_unit =
        file.text(heights, "unit", file.text(heights, "length_unit", lateral_unit));
    const double lateral = metres_in(file, lateral_unit), vertical = metres_in(file, height_unit);
    if (n[0] > (1u << 31) || n[1] > (1u << 31))
      bad_file(filename, "the variable 'heights' is larger than a height map read here");
    Topography topography =
        empty_topography(filename, n[0], n[1], lengths[0] * lateral / std::max<size_t>(n[0], 1),
                         lengths[1] * lateral / std::max<size_t>(n[1], 1));
    file.check(nc_get_var_double(file.id, heights, topography.heights.data()), "the heights cannot be read");
    if (transposed)
      {
        const GridField stored = topography.heights;
        for (std::size_t i = 0; i < n[0]; ++i)
          for (std::size_t j = 0; j < n[1]; ++j)
            topography.heights[i * n[1] + j] = stored[j * n[0] + i];
      }
    for (double &h : topography.heights)
      h *= vertical;
    if (file.has_variable("mask"))
      {
        std::vector<int> mask(topography.heights.size());
        const int        id = file.variable("mask");
        file.check(nc_inq_varndims(file.id, id, &n_dimensions), "the variable 'mask'");
        int mask_dimensions[2];
        if (n_dimensions != 2 ||
            (file.check(nc_inq_vardimid(file.id, id, mask_dimensions), "the variable 'mask'"),
             mask_dimensions[0] != dimensions[0] || mask_dimensions[1] != dimensions[1]))
          bad_file(filename, "the variable 'mask' is not on the dimensions of 'heights'");
        file.check(nc_get_var_int(file.id, id, mask.data()), "the mask cannot be read");
        for (std::size_t i = 0; i < n[0]; ++i)
          for (std::size_t j = 0; j < n[1]; ++j)
            if (mask[transposed ? j * n[0] + i : i * n[1] + j] != 0)
              topography.heights[i * n[1] + j] = std::numeric_limits<double>::quiet_NaN();
      }
    topography.height_unit = height_unit;
    topography.description = "NetCDF";
    return topography;
  }
} // namespace penny
