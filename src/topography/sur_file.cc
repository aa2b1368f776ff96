// Digital Surf's .sur (the layout Gwyddion's surffile.c documents): a
// 512-byte little-endian header, a comment and a private zone of the sizes it
// states, then nx x ny integers of 16 or 32 bits, x the fast index. A height
// is raw * (Z spacing) + (Z offset) in the header's Z unit; with
// "special points" set, raw = zmin - 2 marks a point not measured. The lateral
// spacings are in their own units. One surface object is read (studiable type 2).
#include "input/input_error.h"
#include "topography/topography_formats.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

namespace penny
{
  namespace
  {
    constexpr std::size_t header_size = 512;

    // Little-endian fields at their offsets in the header.
    template <typename T> T field(const std::string &header, const std::size_t offset)
    {
      std::uint64_t bits = 0;
      for (std::size_t k = 0; k < sizeof(T); ++k)
        bits |= std::uint64_t(static_cast<unsigned char>(header[offset + k])) << (8 * k);
      if constexpr (std::is_same_v<T, float>)
        {
          const std::uint32_t narrow = static_cast<std::uint32_t>(bits);
          float               value;
          std::memcpy(&value, &narrow, sizeof value);
          return value;
        }
      else
        return static_cast<T>(static_cast<std::make_unsigned_t<T>>(bits));
    }

    // A unit field: 16 characters padded with blanks or zeros, Latin-1 (0xb5 is mu).
    std::string unit_at(const std::string &header, const std::size_t offset)
    {
      std::string unit;
      for (std::size_t k = offset; k < offset + 16 && header[k] != '\0'; ++k)
        unit += header[k] == '\xb5' ? std::string("\u00b5") : std::string(1, header[k]);
      unit.erase(unit.find_last_not_of(' ') + 1);
      unit.erase(0, unit.find_first_not_of(' '));
      return unit;
    }
  } // namespace

  Topography read_sur(const std::string &filename)
  {
    std::ifstream in(filename, std::ios::binary);
    std::string   header(header_size, '\0');
    if (!in.read(header.data(), header_size))
      bad_file(filename, "is shorter than the 512-byte header of a .sur file");
    if (header.compare(0, 12, "DIGITAL SURF") != 0)
      bad_file(filename, "does not start with 'DIGITAL SURF' (not a .sur file)");
    if (field<std::uint16_t>(header, 12) != 0)
      bad_file(filename, "is in the Macintosh byte order (format 257); the PC format 0 is read here");
    if (const auto type = field<std::uint16_t>(header, 18); type != 2)
      bad_file(filename,
               "holds studiable type " + std::to_string(type) + " (a surface, type 2, is read here)");
    const auto bits = field<std::uint16_t>(header, 98);
    if (bits != 16 && bits != 32)
      bad_file(filename, "states " + std::to_string(bits) + "-bit points (16 or 32 are read here)");
    const bool         special = field<std::uint16_t>(header, 86) != 0;
    const std::int32_t zmin = field<std::int32_t>(header, 100), nx = field<std::int32_t>(header, 108),
                       ny = field<std::int32_t>(header, 112);
    if (field<std::uint32_t>(header, 116) != std::uint64_t(std::max(nx, 0)) * std::max(ny, 0))
      bad_file(filename, "states " + std::to_string(field<std::uint32_t>(header, 116)) + " points, not the " +
                             std::to_string(nx) + " x " + std::to_string(ny) + " of its grid");

    const auto metres = [&](const std::size_t offset) {
      try
        {
          return metres_per(unit_at(header, offset));
        }
      catch (const InputError &error)
        {
          bad_file(filename, error.what());
        }
    };
    // The spacings in their units (delta x and delta y units at 180 and 196), the heights' at 212.
    const double dx = field<float>(header, 120) * metres(180), dy = field<float>(header, 124) * metres(196),
                 dz = field<float>(header, 128) * metres(212), z0 = field<float>(header, 474) * metres(212);
    if (!(std::isfinite(dz) && dz != 0))
      bad_file(filename, "states the Z spacing " + shortest(dz) + " m (must be finite and not zero)");
    if (!std::isfinite(z0))
      bad_file(filename, "states the Z offset " + shortest(z0) + " m (must be finite)");
    // The points must be in the file before the grid is allocated.
    const std::uintmax_t start =
        header_size + field<std::uint16_t>(header, 334) + field<std::uint16_t>(header, 336);
    const std::size_t size = bits / 8, n_x = std::max(nx, 0), n_y = std::max(ny, 0);
    if (std::filesystem::file_size(filename) < start + std::uintmax_t(n_x) * n_y * size)
      bad_file(filename, "is truncated: it holds fewer than the " +
                             std::to_string(std::uintmax_t(n_x) * n_y) + " points its header states");
    Topography topography = empty_topography(filename, nx, ny, dx, dy);
    in.seekg(start);
    std::string bytes(n_x * n_y * size, '\0');
    if (!in.read(bytes.data(), bytes.size()))
      bad_file(filename, "could not be read to the end of its points");
    for (std::size_t j = 0; j < n_y; ++j)
      for (std::size_t i = 0; i < n_x; ++i)
        {
          const std::size_t  k = j * n_x + i;
          const std::int32_t raw =
              size == 2 ? field<std::int16_t>(bytes, k * size) : field<std::int32_t>(bytes, k * size);
          topography.heights[i * n_y + j] =
              special && raw == zmin - 2 ? std::numeric_limits<double>::quiet_NaN() : raw * dz + z0;
        }
    topography.height_unit = unit_at(header, 212);
    std::string instrument = header.substr(50, 30);
    instrument.erase(instrument.find_last_not_of(std::string(" \0", 2)) + 1);
    topography.description =
        "Digital Surf .sur" + (instrument.empty() ? std::string() : ", " + one_line(instrument));
    return topography;
  }
} // namespace penny
