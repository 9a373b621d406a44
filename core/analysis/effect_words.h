#pragma once
// An analysis's effects as a reader meets them: the names the report and
// the project store keep ("water", "joint_law", "imaging.noise_sigma": keys
// of SCENE.md and of the synthetic camera) in the words of a printed page
// ("water pressure", "joint dilation and roughness", "sensor noise (simulated
// camera)"). One table, so the field report and the tablet say the same.
#include <string>
#include <vector>

namespace rockface::analysis {

// The words for one stored effect name; a name this table does not know is
// written with its underscores and dots as spaces (never a raw key).
std::string effect_in_words(const std::string& name);

// "gravity, water pressure; simulated camera: sensor noise, blur": the
// analysis's effects first, then the synthetic camera's (names "imaging.*")
// after one label; "-" when there is none.
std::string effects_in_words(const std::vector<std::string>& names);

}  // namespace rockface::analysis
