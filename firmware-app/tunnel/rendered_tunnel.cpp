#include "firmware-app/tunnel/rendered_tunnel.h"

namespace rockface::app {

camera::RenderedTunnelSpec rendered_tunnel_spec(const storage::SceneTunnelRender& render) {
  camera::RenderedTunnelSpec spec;
  spec.chainage_from = render.from_chainage;
  spec.face_chainage = render.face_chainage;
  spec.section_m = render.section_m;
  spec.facet_m = render.facet_m;
  spec.face_relief_m = render.face_relief_m;
  for (const auto& b : render.breaks)
    spec.breaks.push_back({b.chainage_from, b.chainage_to, b.s_from, b.s_to, b.depth_m});
  return spec;
}

}  // namespace rockface::app
