// The report's readable summary table and its words for a block's motion.
#include "core/analysis/report.h"

#include "core/analysis/effect_words.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/common/number_format.h"

namespace rockface::analysis {

namespace {

std::string fos_text(const std::optional<ReportMode>& mode, std::optional<double> fos) {
  if (!mode) return "-";
  if (mode->type == "none") return "stable";
  if (!fos) return "-";
  if (!std::isfinite(*fos)) return "inf";
  return format_fixed(*fos, 2);
}

std::string mode_text(const std::optional<ReportMode>& mode) {
  if (!mode) return "-";
  std::string t = mode->type;
  if (!mode->planes.empty()) {
    t += " on ";
    for (size_t i = 0; i < mode->planes.size(); ++i) t += (i ? "+" : "") + mode->planes[i];
  }
  return t;
}

std::string pad(const std::string& s, size_t w) {
  return s.size() >= w ? s + " " : s + std::string(w - s.size(), ' ');
}

}  // namespace

std::string event_text(const ReportMotionEvent& e) {
  return e.what + " at " + format_fixed(e.time_s, 2, " s");
}

std::string report_summary(const Report& r) {
  std::ostringstream out;
  // In words, as the field report and the tablet say them (the JSON keeps
  // the keys of SCENE.md).
  out << "effects simulated: " << effects_in_words(r.effects_simulated) << "\n";
  if (!r.pyramids.empty()) {
    size_t removable = 0;
    for (const auto& p : r.pyramids) removable += p.removable;
    out << "\njoint pyramids: " << r.pyramids.size() << " (code x face), " << removable
        << " removable\n";
    out << pad("face", 10) << pad("code", 8) << pad("verdict", 16) << pad("margin", 10)
        << pad("mode", 22) << "FoS\n";
    for (const auto& p : r.pyramids) {
      if (!p.removable && !p.marginal) continue;  // the table lists what can move or might
      const std::string verdict =
          std::string(p.removable ? "removable" : (p.empty ? "empty" : "not removable")) +
          (p.marginal ? "?" : "");
      out << pad(p.face, 10) << pad(p.code, 8) << pad(verdict, 16)
          << pad(format_fixed(p.margin_deg, 2) + " deg", 10) << pad(mode_text(p.mode), 22)
          << fos_text(p.mode, p.fos) << "\n";
    }
    out << "(not listed: pyramids that are firmly not removable; '?' = marginal)\n";
  }
  if (!r.blocks.empty()) {
    // A non-convex trace block has one code per convex piece ("a+b+c" in
    // the report); the table shows the first and how many more.
    bool pieces = false;
    auto code_text = [&](const std::string& code) {
      const size_t n = static_cast<size_t>(std::count(code.begin(), code.end(), '+'));
      if (n == 0) return code;
      pieces = true;
      return code.substr(0, code.find('+')) + " +" + std::to_string(n);
    };
    size_t code_width = 8;
    for (const auto& b : r.blocks) code_width = std::max(code_width, code_text(b.code).size() + 2);
    out << "\nblocks: " << r.blocks.size() << "\n";
    out << pad("block", 10) << pad("source", 8) << pad("code", code_width) << pad("volume m3", 11)
        << pad("verdict", 16) << pad("margin", 10) << pad("mode", 22) << pad("FoS", 8)
        << "rotation\n";
    for (const auto& b : r.blocks) {
      const std::string verdict =
          std::string(!b.finite ? "infinite" : (b.removable ? "removable" : "finite, keyed")) +
          (b.marginal ? "?" : "");
      std::string rotation = "-";
      if (b.rotation) {
        int corners = 0, edges = 0;
        for (const auto& c : b.rotation->corners) corners += c.rotatable;
        for (const auto& e : b.rotation->edges) edges += e.rotatable;
        rotation = std::to_string(corners) + " corner, " + std::to_string(edges) + " edge";
      }
      if (b.remote_axis) rotation += b.remote_axis->found ? "; remote axis" : "; no remote axis";
      out << pad(b.id, 10) << pad(b.source, 8) << pad(code_text(b.code), code_width)
          << pad(b.volume ? format_fixed(*b.volume, 3) : "-", 11) << pad(verdict, 16)
          << pad(format_fixed(b.margin_deg, 2) + " deg", 10) << pad(mode_text(b.mode), 22)
          << pad(fos_text(b.mode, b.fos) + (b.fos_marginal ? "?" : ""), 8) << rotation << "\n";
    }
    if (pieces)
      out << "(code +N: a non-convex block, the code of its first convex piece and N more; all "
             "in the report)\n";
  }
  // The equilibrium path, only where the scene asked for it.
  bool mechanics = false;
  for (const auto& b : r.blocks) mechanics = mechanics || b.mechanics.has_value();
  if (mechanics) {
    out << "\nequilibrium path (strength reduction to the first limit point):\n";
    out << pad("block", 10) << pad("FoS", 8) << pad("failure mode", 14) << pad("stability", 12)
        << "outcome\n";
    for (const auto& b : r.blocks) {
      if (!b.mechanics) continue;
      const ReportMechanics& m = *b.mechanics;
      out << pad(b.id, 10)
          << pad(m.fos_limit_point ? format_fixed(*m.fos_limit_point, 2) : std::string("-"), 8)
          << pad(m.failure_mode.kind, 14) << pad(m.stability, 12) << m.outcome << "\n";
    }
  }
  // The motion after failure, only where the scene asked for it.
  for (const auto& b : r.blocks) {
    if (!b.dynamics) continue;
    out << "\nmotion of " << b.id << " after failure (" << b.dynamics->trigger << "):\n";
    for (const auto& e : b.dynamics->events) out << "  " << event_text(e) << "\n";
  }
  for (const auto& n : r.notes) out << "note: " << n << "\n";
  return out.str();
}

}  // namespace rockface::analysis
