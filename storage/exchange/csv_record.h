#pragma once
// RFC 4180 CSV records, what spreadsheets and Dips write and read: fields
// holding commas, quotes or line breaks are quoted, quotes doubled.
#include <istream>
#include <string>
#include <vector>

namespace rockface::storage {

// `text` as one field (quoted when it needs to be).
std::string csv_field(const std::string& text);

// One record (quoted fields may hold commas, quotes and line breaks); false
// at the end of the input.
bool read_csv_record(std::istream& in, std::vector<std::string>& fields);

}  // namespace rockface::storage
