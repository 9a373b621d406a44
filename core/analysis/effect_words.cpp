#include "core/analysis/effect_words.h"

#include <map>

namespace rockface::analysis {

namespace {

// The prefix the replay gives the synthetic camera's effects
// (firmware-app/replay: "imaging." + camera::SyntheticEffects::simulated()).
constexpr const char* kImaging = "imaging.";

// The analysis's effects (SceneEffects::listed, kinematics::Effect::name).
const std::map<std::string, std::string>& analysis_words() {
  static const std::map<std::string, std::string> table{
      {"gravity", "gravity"},
      {"water", "water pressure"},
      {"seismic", "seismic acceleration"},
      {"insitu_stress", "in-situ stress"},
      {"forces", "applied forces"},
      {"bolts", "bolts"},
      {"shotcrete", "shotcrete"},
      {"joint_law", "joint dilation and roughness"},
      {"dynamics after failure", "motion after failure"},
  };
  return table;
}

// The synthetic camera's (camera::SyntheticEffects::simulated).
const std::map<std::string, std::string>& camera_words() {
  static const std::map<std::string, std::string> table{
      {"distortion", "lens distortion"},
      {"noise_sigma", "sensor noise"},
      {"blur_px", "blur"},
      {"exposure", "exposure"},
      {"flash", "flash"},
      {"lamps", "lamps"},
      {"vignetting", "vignetting"},
      {"sensor", "sensor response"},
      {"jpeg_quality", "JPEG compression"},
      {"wet", "wet patches"},
      {"shotcrete", "shotcrete patches"},
      {"dust", "dust"},
  };
  return table;
}

std::string spaced(std::string s) {
  for (char& c : s)
    if (c == '_' || c == '.') c = ' ';
  return s;
}

}  // namespace

std::string effect_in_words(const std::string& name) {
  const bool camera = name.rfind(kImaging, 0) == 0;
  const std::string bare = camera ? name.substr(std::string(kImaging).size()) : name;
  const auto& table = camera ? camera_words() : analysis_words();
  const auto found = table.find(bare);
  return found != table.end() ? found->second : spaced(bare);
}

std::string effects_in_words(const std::vector<std::string>& names) {
  std::string analysis, camera;
  for (const auto& n : names) {
    std::string& list = n.rfind(kImaging, 0) == 0 ? camera : analysis;
    list += (list.empty() ? "" : ", ") + effect_in_words(n);
  }
  if (!camera.empty())
    analysis += (analysis.empty() ? "" : "; ") + std::string("simulated camera: ") + camera;
  return analysis.empty() ? "-" : analysis;
}

}  // namespace rockface::analysis
