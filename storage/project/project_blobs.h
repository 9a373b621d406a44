#pragma once
// Binary encodings of the array-valued parts of records (meshes, point lists)
// as stored in blob columns. Little-endian, with a magic and counts in front,
// so a damaged or foreign blob is recognised instead of misread.
//
// Mesh blob "RFMESH01": u32 flags (bit 0 texcoords, bit 1 colours), u64
// vertex count, u64 face count, then vertices (3 x f64), faces (3 x i32),
// texcoords (2 x f32, if flagged), colours (3 x u8, if flagged).
// Points blob: n x 3 x f64, nothing else (a length that is not a multiple of
// 24 bytes is damage).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "storage/project/project_records.h"

namespace rockface::storage::blobs {

// Where an encoded mesh goes / comes from piece by piece (a project's mesh
// parts, blob_parts.h), so that a large mesh is never held encoded whole.
using ByteSink = std::function<void(const void* bytes, std::size_t n)>;
// Fills dst with the next n bytes of the stream (n never beyond its size).
using ByteSource = std::function<void(void* dst, std::size_t n)>;

void encode_mesh(const Mesh& mesh, const ByteSink& sink);
std::vector<std::uint8_t> encode_mesh(const Mesh& mesh);
// where: names the record for error messages ("model 3"). size: the stored
// stream's length, which its counts are checked against before allocating.
Mesh decode_mesh(std::uint64_t size, const ByteSource& take, const std::string& where);
Mesh decode_mesh(const std::vector<std::uint8_t>& blob, const std::string& where);

std::vector<std::uint8_t> encode_points(const std::vector<Eigen::Vector3d>& points);
std::vector<Eigen::Vector3d> decode_points(const std::vector<std::uint8_t>& blob,
                                           const std::string& where);

// "jpeg" or "png" from the first bytes of an encoded image; empty if neither.
std::string detect_image_format(const std::vector<std::uint8_t>& bytes);

}  // namespace rockface::storage::blobs
