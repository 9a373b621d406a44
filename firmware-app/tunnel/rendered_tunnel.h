#pragma once
// The scene file's `tunnel.render` as the mock camera's synthetic tunnel
// (camera/synthetic_tunnel.h: the round's surface, its breaks and truth).
#include "camera/synthetic_tunnel.h"
#include "storage/scene/scene_tunnel.h"

namespace rockface::app {

camera::RenderedTunnelSpec rendered_tunnel_spec(const storage::SceneTunnelRender& render);

}  // namespace rockface::app
