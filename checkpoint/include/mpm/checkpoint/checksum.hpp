#pragma once
/// \file checksum.hpp
/// The checksum of a checkpoint's datasets and of the scene text: 64-bit FNV-1a taken over 8-byte words (the
/// tail byte by byte). Each step h <- (h xor w) * p is a bijection of h, so a change of any one word (a flipped
/// byte) always changes the result; at about one multiply per 8 bytes it runs at memory speed. It detects
/// corruption, not tampering.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace mpm::checkpoint {

std::uint64_t checksum(std::span<const std::byte> bytes);
/// The checksum of a text as 16 hexadecimal digits (the scene hash).
std::string checksum_hex(std::string_view text);

}  // namespace mpm::checkpoint
