// ISO 25178-72 (the XML format of ISO 5436-2), .x3p: a zip archive holding
// main.xml, which states the grid (Record1/Axes: CX and CY incremental, with
// their increments in metres; CZ its data type and, for integers, increment
// and offset; Record3/MatrixDimension: SizeX, SizeY, SizeZ = 1), and the binary
// heights it links (Record3/DataLink/PointDataLink: little endian, x the fast
// index), with an optional bit mask of valid points (ValidPointsLink).
#include "input/input_error.h"
#include "topography/topography_formats.h"

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <zip.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <sstream>

namespace penny
{
  namespace
  {
    using Archive = std::unique_ptr<zip_t, decltype(&zip_discard)>;

    // The whole of one member of the archive, whose size must be `size` or, if
    // `size` is 0, at most `largest` bytes (its header's claim is checked
    // before anything is allocated).
    std::string member(const std::string &filename, zip_t *archive, const std::string &name,
                       const zip_uint64_t size, const zip_uint64_t largest = 0)
    {
      zip_stat_t stat;
      zip_stat_init(&stat);
      if (zip_stat(archive, name.c_str(), 0, &stat) != 0 || !(stat.valid & ZIP_STAT_SIZE))
        bad_file(filename, "the archive holds no " + in_quotes(name));
      if (size ? stat.size != size : stat.size > largest)
        bad_file(filename, in_quotes(name) + " holds " + std::to_string(stat.size) + " bytes, not " +
                               (size ? "the " + std::to_string(size) + " its grid needs"
                                     : "at most " + std::to_string(largest)));
      std::unique_ptr<zip_file_t, decltype(&zip_fclose)> file(zip_fopen(archive, name.c_str(), 0),
                                                              &zip_fclose);
      if (!file)
        bad_file(filename, in_quotes(name) + " cannot be opened: " + zip_strerror(archive));
      std::string bytes(stat.size, '\0');
      // libzip checks the member's CRC when a read reaches its end: the read
      // past the last byte must find the end, not an error.
      char              beyond;
      const zip_int64_t read = zip_fread(file.get(), bytes.data(), bytes.size());
      if (read != static_cast<zip_int64_t>(bytes.size()) || zip_fread(file.get(), &beyond, 1) != 0)
        bad_file(filename, in_quotes(name) + " is damaged or truncated" +
                               (zip_file_get_error(file.get())->zip_err != ZIP_ER_OK
                                    ? " (" + std::string(zip_file_strerror(file.get())) + ")"
                                    : std::string()));
      return bytes;
    }

    // The deepest nesting of elements in an XML text, without parsing it
    // (Boost's parser recurses once per level).
    std::size_t nesting_depth(const std::string &xml)
    {
      std::size_t depth = 0, deepest = 0;
      for (std::size_t k = 0; k + 1 < xml.size(); ++k)
        if (xml[k] == '<')
          {
            if (xml[k + 1] == '/')
              depth -= depth > 0;
            else if (xml[k + 1] != '!' && xml[k + 1] != '?')
              {
                const auto close = xml.find('>', k);
                if (close != std::string::npos && xml[close - 1] != '/')
                  deepest = std::max(deepest, ++depth);
              }
          }
      return deepest;
    }

    template <typename Integer> Integer little_endian(const char *bytes)
    {
      std::make_unsigned_t<Integer> value = 0;
      for (std::size_t k = 0; k < sizeof(Integer); ++k)
        value |= std::make_unsigned_t<Integer>(static_cast<unsigned char>(bytes[k])) << (8 * k);
      return static_cast<Integer>(value);
    }

    double value_at(const char *bytes, const char type)
    {
      switch (type)
        {
        case 'I':
          return little_endian<std::int16_t>(bytes);
        case 'L':
          return little_endian<std::int32_t>(bytes);
        case 'F':
          {
            const std::uint32_t bits = little_endian<std::uint32_t>(bytes);
            float               value;
            std::memcpy(&value, &bits, sizeof value);
            return value;
          }
        default:
          {
            const std::uint64_t bits = little_endian<std::uint64_t>(bytes);
            double              value;
            std::memcpy(&value, &bits, sizeof value);
            return value;
          }
        }
    }
  } // namespace

  Topography read_x3p(const std::string &filename)
  {
    int           error = 0;
    const Archive archive(zip_open(filename.c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &error), &zip_discard);
    if (!archive)
      {
        zip_error_t reason;
        zip_error_init_with_code(&reason, error);
        const std::string what = zip_error_strerror(&reason);
        zip_error_fini(&reason);
        bad_file(filename, "is not a readable zip archive, as an .x3p file is (" + what + ")");
      }

    namespace pt = boost::property_tree;
    pt::ptree document;
    // main.xml states a few dozen values: megabytes or deep nesting are not one.
    const std::string main_xml = member(filename, archive.get(), "main.xml", 0, 1 << 24);
    if (nesting_depth(main_xml) > 64)
      bad_file(filename, "main.xml nests its elements deeper than 64 levels");
    std::istringstream xml(main_xml);
    try
      {
        pt::read_xml(xml, document);
      }
    catch (const pt::xml_parser_error &parse)
      {
        bad_file(filename, "main.xml, line " + std::to_string(parse.line()) + ": " + parse.message());
      }
    // The root element carries the namespace's prefix (p:ISO5436_2); its
    // records do not. Comments before it are nodes of their own.
    const auto root_node = std::find_if(document.begin(), document.end(),
                                        [](const auto &node) { return node.first.compare(0, 1, "<") != 0; });
    if (root_node == document.end())
      bad_file(filename, "main.xml has no root element");
    const pt::ptree &root = root_node->second;
    const auto       text = [&](const std::string &path) {
      const auto found = root.get_optional<std::string>(path);
      if (!found)
        bad_file(filename, "main.xml states no " + path);
      return *found;
    };
    const auto number = [&](const std::string &path) {
      const std::string value = text(path);
      char             *end;
      const double      x = std::strtod(value.c_str(), &end);
      if (end == value.c_str() ||
          value.find_first_not_of(" \t\r\n", end - value.c_str()) != std::string::npos || !std::isfinite(x))
        bad_file(filename, "main.xml: " + path + " = " + in_quotes(value) + " is not a number");
      return x;
    };

    if (text("Record1.FeatureType") != "SUR")
      bad_file(filename,
               "main.xml: Record1/FeatureType = " + in_quotes(text("Record1.FeatureType")) +
                   " (an areal surface, SUR, is read here; PRF profiles and PCL point clouds are not)");
    for (const char *axis : {"CX", "CY"})
      if (text(std::string("Record1.Axes.") + axis + ".AxisType") != "I")
        bad_file(filename,
                 std::string("main.xml: Record1/Axes/") + axis +
                     "/AxisType is not I (a grid of equal increments is read here, not listed positions)");
    const char type = text("Record1.Axes.CZ.DataType").front();
    if (std::string("ILFD").find(type) == std::string::npos || text("Record1.Axes.CZ.DataType").size() != 1)
      bad_file(filename, "main.xml: Record1/Axes/CZ/DataType = " +
                             in_quotes(text("Record1.Axes.CZ.DataType")) + " is none of I, L, F, D");
    // Integer heights are scaled by the increment and shifted by the offset (1 and 0 when absent).
    const bool   integers  = type == 'I' || type == 'L';
    const double increment = integers && root.get_optional<std::string>("Record1.Axes.CZ.Increment")
                                 ? number("Record1.Axes.CZ.Increment")
                                 : 1.,
                 offset    = integers && root.get_optional<std::string>("Record1.Axes.CZ.Offset")
                                 ? number("Record1.Axes.CZ.Offset")
                                 : 0.;
    if (increment == 0)
      bad_file(filename, "main.xml: Record1/Axes/CZ/Increment = 0 (the heights' step must not vanish)");
    const double nx = number("Record3.MatrixDimension.SizeX"), ny = number("Record3.MatrixDimension.SizeY"),
                 nz = number("Record3.MatrixDimension.SizeZ");
    if (nz != 1)
      bad_file(filename, "main.xml: Record3/MatrixDimension/SizeZ = " + shortest(nz) +
                             " (one layer of heights is read here)");
    if (nx != std::floor(nx) || ny != std::floor(ny) || nx > 1e9 || ny > 1e9)
      bad_file(filename, "main.xml: Record3/MatrixDimension " + shortest(nx) + " x " + shortest(ny) +
                             " is not a grid of whole numbers of points");
    if (root.get_child_optional("Record3.DataList"))
      bad_file(filename, "the heights are listed in main.xml (Record3/DataList); binary heights "
                         "(Record3/DataLink) are read here");
    if (nx < 3 || ny < 3)
      bad_file(filename, "a grid of " + shortest(nx) + " x " + shortest(ny) +
                             " points (a height map needs 3 x 3 to 2^31 points)");
    // The heights before the grid is allocated: their member must be as large as the grid says.
    const std::size_t size = type == 'I'                  ? 2
                             : type == 'L' || type == 'F' ? 4
                                                          : 8,
                      n_x = static_cast<std::size_t>(nx), n_y = static_cast<std::size_t>(ny);
    const std::string bytes =
        member(filename, archive.get(), text("Record3.DataLink.PointDataLink"), n_x * n_y * size);
    Topography topography = empty_topography(filename, n_x, n_y, number("Record1.Axes.CX.Increment"),
                                             number("Record1.Axes.CY.Increment"));
    // The valid points, one bit each (the lowest bit of a byte first), if the file marks them.
    std::string valid;
    if (const auto link = root.get_optional<std::string>("Record3.DataLink.ValidPointsLink"))
      {
        valid = member(filename, archive.get(), *link, 0, (n_x * n_y + 7) / 8 + 4096);
        if (valid.size() < (n_x * n_y + 7) / 8)
          bad_file(filename, in_quotes(*link) + " holds " + std::to_string(valid.size()) +
                                 " bytes, fewer than one bit per point");
      }
    for (std::size_t j = 0; j < n_y; ++j)
      for (std::size_t i = 0; i < n_x; ++i)
        {
          const std::size_t k = j * n_x + i;
          const bool measured = valid.empty() || (static_cast<unsigned char>(valid[k / 8]) >> (k % 8)) & 1u;
          topography.heights[i * n_y + j] = measured ? offset + increment * value_at(&bytes[k * size], type)
                                                     : std::numeric_limits<double>::quiet_NaN();
        }
    topography.height_unit = "m";
    topography.description =
        "ISO 25178-72 .x3p, " + root.get<std::string>("Record2.Instrument.Model", "instrument not stated");
    return topography;
  }
} // namespace penny
