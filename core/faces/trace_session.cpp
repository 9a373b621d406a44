#include "core/faces/trace_session.h"

#include <cstring>
#include <unordered_map>

namespace rockface::faces {

namespace {

// The bits of the double: exact, and far cheaper than text.
void put(std::string& key, double x) {
  char bytes[sizeof x];
  std::memcpy(bytes, &x, sizeof x);
  key.append(bytes, sizeof x);
}

void put(std::string& key, const Eigen::Vector3d& x) {
  put(key, x.x());
  put(key, x.y());
  put(key, x.z());
}

void put(std::string& key, const std::string& s) {
  key += std::to_string(s.size()) + ":" + s + ",";
}

void put_group(std::string& key, const TraceNetwork& net, int g) {
  if (g < 0) {
    key += "patch edge,";
    return;
  }
  const PlaneGroup& pg = net.groups()[g];
  put(key, pg.name);
  put(key, pg.plane.plane.normal);
  put(key, pg.plane.plane.offset);
  key += pg.plane.source == TracePlaneSource::Fitted ? "fitted," : "given,";
  put(key, pg.plane.uncertainty);
  if (pg.joint) {
    key += "joint " + std::to_string(pg.joint->index) + ",";
    put(key, pg.joint->id);
    put(key, pg.joint->friction ? *pg.joint->friction : -1.0);
    put(key, pg.joint->cohesion);
  }
}

}  // namespace

std::string trace_region_key(const TraceNetwork& net, const SurfaceLoops& loops, int r) {
  const SurfaceRegion& region = loops.regions()[r];
  std::string key;
  for (const auto& loop : region.loops) {
    key += "loop;";
    for (size_t i = 0; i < loop.size(); ++i) {
      const int h = loop[i], nx = loop[(i + 1) % loop.size()];
      put(key, net.vertices()[net.origin(h)]);
      put(key, net.vertices()[net.target(h)]);
      put_group(key, net, net.edges()[h / 2].group);
      key += std::to_string(loops.faces()[loops.half_edge_face()[h]].patch) + ",";
      // The turn at the corner (reflex or not).
      const AroundVertex& av = net.around()[net.target(h)];
      put(key, av.angle[net.slot(nx)]);
      put(key, av.angle[net.slot(h ^ 1)]);
      put(key, av.total);
    }
  }
  key += "groups;";
  for (int g : region.groups) put_group(key, net, g);
  key += "faces;";
  for (int f : region.faces) {
    const SurfaceFace& face = loops.faces()[f];
    key += std::to_string(face.patch) + (face.area <= 0 ? "-," : "+,");
    for (int h : face.half_edges) put(key, net.vertices()[net.origin(h)]);
  }
  key += "patches;";
  for (int p : region.patches) key += std::to_string(p) + ",";
  return key;
}

TraceSession::TraceSession(const std::vector<PatchInput>& patches,
                           const NetworkOptions& network_options, const TraceBlockOptions& options)
    : surface_(FreeSurface::build(patches, options.snap_tolerance)),
      network_options_(network_options),
      options_(options) {}

const std::vector<TraceBlock>& TraceSession::update(const std::vector<TraceInput>& traces,
                                                    Progress& progress) {
  network_ = TraceNetwork::build(surface_, traces, network_options_);
  loops_ = SurfaceLoops::find(network_, surface_);
  std::unordered_map<std::string, int> group_index;
  for (size_t g = 0; g < network_.groups().size(); ++g)
    group_index[network_.groups()[g].name] = static_cast<int>(g);
  std::vector<TraceBlock> old = std::move(blocks_);
  std::vector<bool> taken(old.size(), false);
  blocks_.clear();
  recomputed_ = reused_ = 0;
  const size_t n = loops_.regions().size();
  blocks_.reserve(n);  // no reallocation, which copies blocks (their move is not noexcept)
  std::vector<std::string> keys(n);
  std::unordered_map<std::string, int> cache;
  cache.reserve(n);
  for (size_t r = 0; r < n; ++r) {
    keys[r] = trace_region_key(network_, loops_, static_cast<int>(r));
    std::optional<TraceBlock> block;
    const auto hit = cache_.find(keys[r]);
    // A block is moved out once; a second region with the same key (the
    // same inputs, so the same block) computes its own.
    if (hit != cache_.end() && (hit->second < 0 || !taken[hit->second])) {
      ++reused_;
      if (hit->second >= 0) {
        taken[hit->second] = true;
        block = std::move(old[hit->second]);
        // The same block in the new map's numbering.
        block->region = static_cast<int>(r);
        block->traces = loops_.regions()[r].traces;
        for (auto& p : block->planes)
          if (p.kind == blocks::PlaneKind::Joint) p.group = group_index.at(p.name);
      }
    } else {
      progress.step("blocks from trace loops", static_cast<double>(r) / static_cast<double>(n));
      ++recomputed_;
      block = trace_block(surface_, network_, loops_, static_cast<int>(r), options_);
    }
    if (block)
      blocks_.push_back(std::move(*block));
    else
      cache.emplace(keys[r], -1);
  }
  order_trace_blocks(blocks_);
  for (size_t i = 0; i < blocks_.size(); ++i)
    cache.emplace(std::move(keys[blocks_[i].region]), static_cast<int>(i));
  cache_ = std::move(cache);
  return blocks_;
}

}  // namespace rockface::faces
