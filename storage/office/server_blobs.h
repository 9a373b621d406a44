#pragma once
// One photograph read from the office server when a page shows it (issue
// 46: a visit page pulled every photograph of the tunnel to show one
// visit's): found by its image record's uuid, read chunk by chunk under
// the connection's role (row-level security: only a photograph of a
// record the role may read), and checked against its SHA-256.
#include <cstdint>
#include <string>
#include <vector>

#include "storage/office/pg_connection.h"

namespace rockface::storage::office {

struct ServerPhotograph {
  std::string format;  // "jpg" | "png" as the image row keeps it
  std::vector<std::uint8_t> bytes;
};

// Throws InputError when the image is not on the server for this role, or
// its bytes are missing, truncated or corrupt there.
ServerPhotograph read_server_photograph(Connection& c, const std::string& image_uuid);

}  // namespace rockface::storage::office
