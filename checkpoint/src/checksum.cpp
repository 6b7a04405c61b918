#include "mpm/checkpoint/checksum.hpp"

#include <fmt/format.h>

#include <cstring>

namespace mpm::checkpoint {

std::uint64_t checksum(std::span<const std::byte> bytes) {
  constexpr std::uint64_t prime = 0x100000001b3ULL;
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a offset basis
  const std::size_t words = bytes.size() / 8;
  for (std::size_t k = 0; k < words; ++k) {
    std::uint64_t w = 0;
    std::memcpy(&w, bytes.data() + 8 * k, 8);
    h = (h ^ w) * prime;
  }
  for (std::size_t k = 8 * words; k < bytes.size(); ++k) h = (h ^ static_cast<std::uint64_t>(bytes[k])) * prime;
  return (h ^ bytes.size()) * prime;  // the length too: trailing zero bytes count
}

std::string checksum_hex(std::string_view text) {
  return fmt::format("{:016x}", checksum(std::as_bytes(std::span<const char>(text.data(), text.size()))));
}

}  // namespace mpm::checkpoint
