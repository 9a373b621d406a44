#pragma once
// SHA-256 of a byte stream fed in pieces (OpenSSL's EVP digest), so that a
// photograph is hashed while it is read or sent, never held twice.
#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace rockface::storage::office {

class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  void add(std::span<const std::uint8_t> bytes);
  void add(std::string_view text);
  // Lower-case hex of the digest; the object is spent afterwards.
  std::string hex();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

std::string sha256_hex(std::span<const std::uint8_t> bytes);
std::string sha256_hex(std::string_view text);

}  // namespace rockface::storage::office
