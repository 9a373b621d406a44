#pragma once
// A visit's face outline in words (issue 27), for the Mapping screen's
// status line and the field report: the outline a geologist marked on the
// tablet is stored as the flat pieces of the 3D image it covers
// (core/measure/outline_pieces.h), one area row per piece labelled F1a,
// F1b, ... (a flat face: one row, F1), and is told as one outline:
// "face outline F1: 2 flat pieces, 12.0° apart, RMS 6 mm / 7 mm".
#include <string>
#include <vector>

#include "storage/project/project_records.h"

namespace rockface::storage {

// Whether an area row is part of the visit's mapped face: no free face (no
// rock side) and no joint measured from it ("area LABEL").
bool is_face_outline(const Measurement& m, const std::vector<Joint>& joints);

// The outline a piece belongs to: its label without the piece's letter
// ("F1b" -> "F1"; "F1" and "FACE_W" stay).
std::string outline_of_piece(const std::string& label);

// One line per outline among `measurements` (in their order), with its
// pieces' angle apart (the largest between two of them), their RMS off
// their planes, and the notes stored with them.
std::vector<std::string> face_outline_words(const std::vector<Measurement>& measurements,
                                            const std::vector<Joint>& joints);

// The same for a printed page, where a face of many outlines would fill it:
// the outlines of one flat piece with nothing noted told in one line ("5
// face outlines, each one flat piece (FACE_W, ..., WALL_E), RMS at most 0
// mm"), then one line per other outline as face_outline_words tells it.
std::vector<std::string> face_outline_summary(const std::vector<Measurement>& measurements,
                                              const std::vector<Joint>& joints);

}  // namespace rockface::storage
