#include "storage/office/sha256.h"

#include <openssl/evp.h>

#include "core/common/error.h"

namespace rockface::storage::office {

struct Sha256::State {
  EVP_MD_CTX* ctx = nullptr;
};

Sha256::Sha256() : state_(std::make_unique<State>()) {
  state_->ctx = EVP_MD_CTX_new();
  if (!state_->ctx || EVP_DigestInit_ex(state_->ctx, EVP_sha256(), nullptr) != 1)
    throw Error("SHA-256: cannot start a digest (OpenSSL)");
}

Sha256::~Sha256() {
  if (state_->ctx) EVP_MD_CTX_free(state_->ctx);
}

void Sha256::add(std::span<const std::uint8_t> bytes) {
  if (!bytes.empty() && EVP_DigestUpdate(state_->ctx, bytes.data(), bytes.size()) != 1)
    throw Error("SHA-256: digest update failed (OpenSSL)");
}

void Sha256::add(std::string_view text) {
  add({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

std::string Sha256::hex() {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int n = 0;
  if (EVP_DigestFinal_ex(state_->ctx, digest, &n) != 1)
    throw Error("SHA-256: digest final failed (OpenSSL)");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * n);
  for (unsigned int i = 0; i < n; ++i) {
    out += kHex[digest[i] >> 4];
    out += kHex[digest[i] & 15];
  }
  return out;
}

std::string sha256_hex(std::span<const std::uint8_t> bytes) {
  Sha256 h;
  h.add(bytes);
  return h.hex();
}

std::string sha256_hex(std::string_view text) {
  Sha256 h;
  h.add(text);
  return h.hex();
}

}  // namespace rockface::storage::office
