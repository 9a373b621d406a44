#pragma once
// What the analysis input must be (SCENE.md, docs/scene-extensions.md), checked
// over the values: numbers finite and in their ranges, enough points and
// vertices, words among the known ones, ids unique and every id referred to
// known. The scene reader (storage/scene/scene.h) runs it on what it parsed, the
// tablet on what it built from the project's rows: one check, one refusal,
// word for word, whichever way the input came.
//
// A refusal is an InputError naming the input's `source` and the field path,
// as the scene reader names them: "S.json: joints[2].dip: 95 is outside [0, 90]".
#include <string>

#include "core/analysis/analysis_input.h"

namespace rockface::analysis {

// Throws InputError at the first value the input may not hold.
void check_analysis_input(const AnalysisInput& input);

// A free face's rock side from its word: "upper" is half-space code 0,
// "lower" code 1; any other word is refused at `where` (the source and the
// field path, "S.json: free_faces[1].rock_side").
int rock_side_code(const std::string& word, const std::string& where);

// A number as a JSON writer writes it (nlohmann's shortest round trip: "95",
// "0.5", "1e-07"; a whole number without ".0"), for refusals that quote it.
std::string number_as_written(double v);

}  // namespace rockface::analysis
