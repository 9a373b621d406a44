#include "storage/exchange/las_reader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <optional>
#include <vector>

#include "core/common/error.h"

namespace rockface::storage {

namespace las_detail {

// LAS is little-endian throughout.
template <typename T>
T little(std::string_view bytes, std::size_t at) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, bytes.data() + at, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
  T v;
  std::memcpy(&v, raw, sizeof(T));
  return v;
}

// The header's size up to its last field, by minor version (LAS 1.0 to 1.2:
// 227 bytes; 1.3 adds the waveform start; 1.4 the extended counts).
std::size_t header_size_of(int minor) {
  if (minor <= 2) return 227;
  if (minor == 3) return 235;
  return 375;
}

// The fewest bytes a record of `format` takes, and where its RGB starts
// (0: the format has no colour).
struct RecordLayout {
  std::size_t length = 0;
  std::size_t rgb_at = 0;
};

std::optional<RecordLayout> layout_of(int format) {
  switch (format) {
    case 0:
      return RecordLayout{20, 0};
    case 1:
      return RecordLayout{28, 0};
    case 2:
      return RecordLayout{26, 20};
    case 3:
      return RecordLayout{34, 28};
    case 6:
      return RecordLayout{30, 0};
    case 7:
      return RecordLayout{36, 30};
    case 8:
      return RecordLayout{38, 30};
    default:
      return std::nullopt;
  }
}

}  // namespace las_detail

namespace {

// A LAS file's bytes: its head (the header, at least its first 375 bytes or
// the whole file when shorter), its size, and any range of it on demand.
struct LasBytes {
  std::string_view head;
  std::uint64_t size = 0;
  std::function<std::string_view(std::uint64_t at, std::size_t n)> fetch;
};

// The points are taken in chunks of about 8 MiB of records.
constexpr std::size_t kChunkBytes = std::size_t{8} << 20;

ImportedSurface parse_las_bytes(const LasBytes& file, const std::string& source) {
  using las_detail::little;
  const std::string_view bytes = file.head;
  if (bytes.size() < 4 || bytes.substr(0, 4) != "LASF")
    throw InputError(source, "not a LAS file (it does not begin with LASF)");
  if (file.size < 227)
    throw InputError(source, "the header is cut short (" + std::to_string(file.size) +
                                 " bytes; a LAS header takes at least 227)");
  const int major = static_cast<unsigned char>(bytes[24]);
  const int minor = static_cast<unsigned char>(bytes[25]);
  const std::string version = std::to_string(major) + "." + std::to_string(minor);
  if (major != 1 || minor > 4)
    throw InputError(source, "header: LAS version " + version + " (1.0 to 1.4 are read)");
  const std::size_t header_size = little<std::uint16_t>(bytes, 94);
  const std::size_t point_offset = little<std::uint32_t>(bytes, 96);
  const int format_byte = static_cast<unsigned char>(bytes[104]);
  const std::size_t record_length = little<std::uint16_t>(bytes, 105);
  const std::uint64_t legacy_count = little<std::uint32_t>(bytes, 107);
  if (header_size < las_detail::header_size_of(minor))
    throw InputError(source, "header: its size " + std::to_string(header_size) +
                                 " is less than LAS " + version + "'s " +
                                 std::to_string(las_detail::header_size_of(minor)) + " bytes");
  if (header_size > file.size)
    throw InputError(source, "header: its size " + std::to_string(header_size) +
                                 " is more than the file's " + std::to_string(file.size) +
                                 " bytes");
  if (point_offset < header_size || point_offset > file.size)
    throw InputError(source, "header: the points are said to start at byte " +
                                 std::to_string(point_offset) + ", outside the file's " +
                                 std::to_string(file.size) + " bytes after its header");
  // LASzip marks a compressed file by setting the format's two high bits.
  if (format_byte & 0xC0)
    throw InputError(source, "a LAZ (compressed LAS) file: decompress it first, e.g. `laszip -i " +
                                 source + " -o cloud.las` (LAStools), `pdal translate " + source +
                                 " cloud.las` (PDAL) or CloudCompare's Save as LAS");
  const auto layout = las_detail::layout_of(format_byte);
  if (!layout)
    throw InputError(source, "header: point data record format " + std::to_string(format_byte) +
                                 " (formats 0 to 3 and 6 to 8 are read)");
  if (format_byte >= 6 && minor < 4)
    throw InputError(source, "header: point format " + std::to_string(format_byte) +
                                 " needs LAS 1.4, the file says " + version);
  if (record_length < layout->length)
    throw InputError(source, "header: a record of point format " + std::to_string(format_byte) +
                                 " takes " + std::to_string(layout->length) +
                                 " bytes, the header says " + std::to_string(record_length));
  std::uint64_t count = legacy_count;
  if (minor == 4) {
    const std::uint64_t wide = little<std::uint64_t>(bytes, 247);
    if (legacy_count != 0 && legacy_count != wide)
      throw InputError(source, "header: the point count " + std::to_string(legacy_count) +
                                   " and the 64-bit point count " + std::to_string(wide) +
                                   " disagree");
    count = wide;
  }
  const std::uint64_t room = (file.size - point_offset) / record_length;
  if (count > room)
    throw InputError(source, "header: " + std::to_string(count) + " points of " +
                                 std::to_string(record_length) + " bytes do not fit in the " +
                                 std::to_string(file.size - point_offset) + " bytes after byte " +
                                 std::to_string(point_offset));
  Eigen::Vector3d scale, offset, lo, hi;
  for (int k = 0; k < 3; ++k) {
    scale[k] = little<double>(bytes, 131 + 8 * static_cast<std::size_t>(k));
    offset[k] = little<double>(bytes, 155 + 8 * static_cast<std::size_t>(k));
    hi[k] = little<double>(bytes, 179 + 16 * static_cast<std::size_t>(k));
    lo[k] = little<double>(bytes, 187 + 16 * static_cast<std::size_t>(k));
    const std::string axis(1, "XYZ"[k]);
    if (!std::isfinite(scale[k]) || scale[k] == 0)
      throw InputError(source, "header: the " + axis +
                                   " scale factor is not a finite non-zero "
                                   "number");
    if (!std::isfinite(offset[k]))
      throw InputError(source, "header: the " + axis + " offset is not a finite number");
    if (!std::isfinite(lo[k]) || !std::isfinite(hi[k]) || lo[k] > hi[k])
      throw InputError(source, "header: the " + axis + " bounds are not a finite range");
  }

  ImportedSurface out;
  out.format = "LAS " + version + " point format " + std::to_string(format_byte);
  auto& mesh = out.mesh;
  mesh.vertices.reserve(count);
  if (layout->rgb_at) mesh.colours.reserve(count);
  // Without RGB (formats 0, 1, 6) the intensity is the picture
  // (intensity_grey.h); every format holds it at byte 12.
  if (!layout->rgb_at) out.intensities.reserve(count);
  std::vector<std::array<std::uint16_t, 3>> rgb16;
  if (layout->rgb_at) rgb16.reserve(count);
  std::uint16_t brightest = 0;
  // A point may lie outside the header's bounds by the rounding of the
  // bounds themselves: half a scale unit, and the doubles' own rounding.
  const Eigen::Vector3d slack = scale.cwiseAbs() + 1e-9 * (lo.cwiseAbs() + hi.cwiseAbs());
  const std::uint64_t per_chunk = std::max<std::uint64_t>(1, kChunkBytes / record_length);
  std::string_view chunk;
  std::uint64_t chunk_first = 0;
  for (std::uint64_t n = 0; n < count; ++n) {
    if (n == 0 || n - chunk_first == per_chunk) {
      chunk_first = n;
      const std::uint64_t records = std::min(per_chunk, count - n);
      chunk = file.fetch(point_offset + n * record_length,
                         static_cast<std::size_t>(records * record_length));
    }
    const std::size_t at = static_cast<std::size_t>((n - chunk_first) * record_length);
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k)
      p[k] =
          little<std::int32_t>(chunk, at + 4 * static_cast<std::size_t>(k)) * scale[k] + offset[k];
    for (int k = 0; k < 3; ++k)
      if (p[k] < lo[k] - slack[k] || p[k] > hi[k] + slack[k])
        throw InputError(source, "point " + std::to_string(n) + ": " + "XYZ"[k] + " " +
                                     std::to_string(p[k]) + " lies outside the header's bounds [" +
                                     std::to_string(lo[k]) + ", " + std::to_string(hi[k]) +
                                     "]: the header does not describe its points");
    mesh.vertices.push_back(p);
    if (!layout->rgb_at) out.intensities.push_back(little<std::uint16_t>(chunk, at + 12));
    if (layout->rgb_at) {
      std::array<std::uint16_t, 3> c{};
      for (std::size_t k = 0; k < 3; ++k) {
        c[k] = little<std::uint16_t>(chunk, at + layout->rgb_at + 2 * k);
        brightest = std::max(brightest, c[k]);
      }
      rgb16.push_back(c);
    }
  }
  // The specification's colours are 16-bit; writers that put 8-bit values
  // in them are common (their brightest channel stays below 256).
  const int shift = brightest > 255 ? 8 : 0;
  for (const auto& c : rgb16)
    mesh.colours.push_back({static_cast<std::uint8_t>(c[0] >> shift),
                            static_cast<std::uint8_t>(c[1] >> shift),
                            static_cast<std::uint8_t>(c[2] >> shift)});
  take_datum(out);
  return out;
}

}  // namespace

ImportedSurface parse_las(std::string_view bytes, const std::string& source) {
  LasBytes file;
  file.head = bytes;
  file.size = bytes.size();
  file.fetch = [bytes](std::uint64_t at, std::size_t n) {
    return bytes.substr(static_cast<std::size_t>(at), n);
  };
  return parse_las_bytes(file, source);
}

ImportedSurface read_las_file(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(source, "cannot open the file");
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(source, "cannot read the file's size");
  // 375 bytes: a LAS 1.4 header, the longest.
  std::string head(static_cast<std::size_t>(std::min<std::uint64_t>(size, 375)), '\0');
  if (!in.read(head.data(), static_cast<std::streamsize>(head.size())))
    throw InputError(source, "cannot read the file");
  std::string buffer;
  LasBytes file;
  file.head = head;
  file.size = size;
  file.fetch = [&](std::uint64_t at, std::size_t n) {
    buffer.resize(n);
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(buffer.data(), static_cast<std::streamsize>(n)))
      throw InputError(source, "cannot read the file at byte " + std::to_string(at));
    return std::string_view(buffer);
  };
  return parse_las_bytes(file, source);
}

}  // namespace rockface::storage
