#include "core/photogrammetry/surface/face_traces.h"

#include "core/common/error.h"
#include "core/photogrammetry/surface/pixel_lookup.h"

namespace rockface::photogrammetry {

std::vector<FaceTrace> traces_in_face_frame(const std::vector<FaceImage>& images,
                                            const FaceRegistration& face,
                                            const std::vector<ImageTrace>& traces,
                                            const FaceTraceOptions& options) {
  std::vector<PixelLookup> lookups;
  for (const auto& image : images) lookups.emplace_back(image.mesh);

  std::vector<TracePiece> pieces;
  for (const auto& t : traces) {
    if (t.image < 0 || static_cast<std::size_t>(t.image) >= images.size())
      throw InputError("trace " + t.label,
                       "names image " + std::to_string(t.image) + ", which is not given");
    TracePiece piece{t.label, t.joint, t.image, {}};
    for (const auto& px : t.pixels) {
      const int v = lookups[t.image].nearest(px);
      if (v >= 0)
        piece.points.push_back(
            face.images[t.image].to_face.apply(images[t.image].mesh.vertices[v]));
    }
    if (piece.points.size() < 2) continue;  // off the reconstructed surface
    pieces.push_back(std::move(piece));
  }
  return join_trace_pieces(pieces, options);
}

}  // namespace rockface::photogrammetry
