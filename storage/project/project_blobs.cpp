#include "storage/project/project_blobs.h"

#include <bit>
#include <cstring>

#include "core/common/error.h"

namespace rockface::storage::blobs {

static_assert(std::endian::native == std::endian::little,
              "project blobs are little-endian; a big-endian port needs byte swapping here");

namespace {

constexpr char kMeshMagic[8] = {'R', 'F', 'M', 'E', 'S', 'H', '0', '1'};
constexpr std::uint32_t kHasTexcoords = 1u << 0;
constexpr std::uint32_t kHasColours = 1u << 1;

template <typename T>
void append_bytes(std::vector<std::uint8_t>& out, const T& value) {
  const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
  out.insert(out.end(), p, p + sizeof(T));
}

class Reader {
 public:
  Reader(const std::vector<std::uint8_t>& blob, const std::string& where)
      : blob_(blob), where_(where) {}
  template <typename T>
  T get() {
    T value;
    take(&value, sizeof(T));
    return value;
  }
  void take(void* dst, std::size_t n) {
    if (n > blob_.size() - pos_)
      throw Error(where_ + ": stored data is damaged (truncated at byte " + std::to_string(pos_) +
                  " of " + std::to_string(blob_.size()) + ")");
    std::memcpy(dst, blob_.data() + pos_, n);
    pos_ += n;
  }
  std::size_t remaining() const { return blob_.size() - pos_; }

 private:
  const std::vector<std::uint8_t>& blob_;
  const std::string& where_;
  std::size_t pos_ = 0;
};

}  // namespace

namespace {

void check_mesh(const Mesh& mesh) {
  const std::size_t nv = mesh.vertices.size();
  if (!mesh.texcoords.empty() && mesh.texcoords.size() != nv)
    throw InputError("model mesh", "texcoords: " + std::to_string(mesh.texcoords.size()) + " for " +
                                       std::to_string(nv) + " vertices");
  if (!mesh.colours.empty() && mesh.colours.size() != nv)
    throw InputError("model mesh", "colours: " + std::to_string(mesh.colours.size()) + " for " +
                                       std::to_string(nv) + " vertices");
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (std::int32_t v : mesh.faces[f])
      if (v < 0 || static_cast<std::size_t>(v) >= nv)
        throw InputError("model mesh", "faces[" + std::to_string(f) + "] refers to vertex " +
                                           std::to_string(v) + " of " + std::to_string(nv));
}

// The arrays are written and read whole: a vertex is three doubles, a face
// three i32, a texcoord two f32, a colour three bytes, with no padding, which
// is the blob's layout on a little-endian machine.
static_assert(sizeof(Eigen::Vector3d) == 24);
static_assert(sizeof(std::array<std::int32_t, 3>) == 12);
static_assert(sizeof(std::array<float, 2>) == 8);
static_assert(sizeof(std::array<std::uint8_t, 3>) == 3);

}  // namespace

void encode_mesh(const Mesh& mesh, const ByteSink& sink) {
  check_mesh(mesh);
  std::uint32_t flags = 0;
  if (!mesh.texcoords.empty()) flags |= kHasTexcoords;
  if (!mesh.colours.empty()) flags |= kHasColours;
  std::vector<std::uint8_t> head(std::begin(kMeshMagic), std::end(kMeshMagic));
  append_bytes(head, flags);
  append_bytes(head, static_cast<std::uint64_t>(mesh.vertices.size()));
  append_bytes(head, static_cast<std::uint64_t>(mesh.faces.size()));
  sink(head.data(), head.size());
  sink(mesh.vertices.data(), mesh.vertices.size() * sizeof(mesh.vertices[0]));
  sink(mesh.faces.data(), mesh.faces.size() * sizeof(mesh.faces[0]));
  sink(mesh.texcoords.data(), mesh.texcoords.size() * sizeof(mesh.texcoords[0]));
  sink(mesh.colours.data(), mesh.colours.size() * sizeof(mesh.colours[0]));
}

std::vector<std::uint8_t> encode_mesh(const Mesh& mesh) {
  std::vector<std::uint8_t> out;
  out.reserve(8 + 4 + 16 + mesh.vertices.size() * (24 + 8 + 3) + mesh.faces.size() * 12);
  encode_mesh(mesh, [&](const void* bytes, std::size_t n) {
    const auto* p = static_cast<const std::uint8_t*>(bytes);
    out.insert(out.end(), p, p + n);
  });
  return out;
}

Mesh decode_mesh(std::uint64_t size, const ByteSource& take, const std::string& where) {
  std::uint64_t remaining = size;
  const auto get = [&](void* dst, std::uint64_t n) {
    if (n > remaining)
      throw Error(where + ": stored data is damaged (truncated at byte " +
                  std::to_string(size - remaining) + " of " + std::to_string(size) + ")");
    if (n > 0) take(dst, static_cast<std::size_t>(n));
    remaining -= n;
  };
  char magic[8];
  get(magic, sizeof(magic));
  if (std::memcmp(magic, kMeshMagic, sizeof(magic)) != 0)
    throw Error(where + ": stored mesh is damaged or of an unknown format");
  std::uint32_t flags = 0;
  std::uint64_t nv = 0, nf = 0;
  get(&flags, sizeof(flags));
  get(&nv, sizeof(nv));
  get(&nf, sizeof(nf));
  const std::uint64_t per_vertex =
      24 + ((flags & kHasTexcoords) ? 8 : 0) + ((flags & kHasColours) ? 3 : 0);
  // Check the counts against the stored size before allocating what they claim.
  if (nv > remaining / per_vertex || nf > remaining / 12 || nv * per_vertex + nf * 12 != remaining)
    throw Error(where + ": stored mesh is damaged (counts do not match its size)");
  Mesh mesh;
  mesh.vertices.resize(nv);
  get(mesh.vertices.data(), nv * sizeof(mesh.vertices[0]));
  mesh.faces.resize(nf);
  get(mesh.faces.data(), nf * sizeof(mesh.faces[0]));
  for (const auto& f : mesh.faces)
    for (const std::int32_t i : f)
      if (i < 0 || static_cast<std::uint64_t>(i) >= nv)
        throw Error(where + ": stored mesh is damaged (face refers to vertex " + std::to_string(i) +
                    ")");
  if (flags & kHasTexcoords) {
    mesh.texcoords.resize(nv);
    get(mesh.texcoords.data(), nv * sizeof(mesh.texcoords[0]));
  }
  if (flags & kHasColours) {
    mesh.colours.resize(nv);
    get(mesh.colours.data(), nv * sizeof(mesh.colours[0]));
  }
  return mesh;
}

Mesh decode_mesh(const std::vector<std::uint8_t>& blob, const std::string& where) {
  std::size_t at = 0;
  return decode_mesh(
      blob.size(),
      [&](void* dst, std::size_t n) {
        std::memcpy(dst, blob.data() + at, n);
        at += n;
      },
      where);
}

std::vector<std::uint8_t> encode_points(const std::vector<Eigen::Vector3d>& points) {
  std::vector<std::uint8_t> out;
  out.reserve(points.size() * 24);
  for (const auto& p : points) {
    append_bytes(out, p.x());
    append_bytes(out, p.y());
    append_bytes(out, p.z());
  }
  return out;
}

std::vector<Eigen::Vector3d> decode_points(const std::vector<std::uint8_t>& blob,
                                           const std::string& where) {
  if (blob.size() % 24 != 0)
    throw Error(where + ": stored points are damaged (" + std::to_string(blob.size()) +
                " bytes is not a whole number of points)");
  Reader in(blob, where);
  std::vector<Eigen::Vector3d> points(blob.size() / 24);
  for (auto& p : points) {
    const double x = in.get<double>(), y = in.get<double>(), z = in.get<double>();
    p = Eigen::Vector3d(x, y, z);
  }
  return points;
}

std::string detect_image_format(const std::vector<std::uint8_t>& bytes) {
  static constexpr std::uint8_t kJpeg[] = {0xFF, 0xD8, 0xFF};
  static constexpr std::uint8_t kPng[] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  if (bytes.size() >= sizeof(kJpeg) && std::memcmp(bytes.data(), kJpeg, sizeof(kJpeg)) == 0)
    return "jpeg";
  if (bytes.size() >= sizeof(kPng) && std::memcmp(bytes.data(), kPng, sizeof(kPng)) == 0)
    return "png";
  return {};
}

}  // namespace rockface::storage::blobs
